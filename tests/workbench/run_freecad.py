#!/usr/bin/python3
"""Run FreeCAD for a test in a throw-away HOME, with its own Xvfb server for GUI tests.

    run_freecad.py [--gui] [--timeout S] --out DIR -- freecadcmd -t TestX -M workbench ...

FreeCAD writes ~/.config, ~/.local/share and ~/.cache at every start, so HOME is a temp dir.
--gui starts `Xvfb -displayfd` (it picks a free display itself), points DISPLAY at it and
stops it by its pid afterwards. The child runs in its own session and is killed with
everything it started on timeout. FRAMEFIX_TEST_OUT=DIR is where tests put screenshots.
"""
import argparse
import os
import shutil
import signal
import subprocess
import sys
import tempfile


def start_xvfb(env):
    read_fd, write_fd = os.pipe()
    xvfb = subprocess.Popen(["Xvfb", "-displayfd", str(write_fd), "-screen", "0", "1920x1200x24",
                             "-nolisten", "tcp"], pass_fds=(write_fd,), env=env,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(write_fd)
    with os.fdopen(read_fd) as f:
        display = f.readline().strip()
    if not display:
        xvfb.kill()
        sys.exit("run_freecad: Xvfb did not start")
    return xvfb, ":" + display


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--gui", action="store_true")
    parser.add_argument("--timeout", type=float, default=600)
    parser.add_argument("--out", required=True)
    parser.add_argument("command", nargs=argparse.REMAINDER)
    args = parser.parse_args()
    command = args.command[1:] if args.command[:1] == ["--"] else args.command
    os.makedirs(args.out, exist_ok=True)
    home = tempfile.mkdtemp(prefix="framefix_home_")
    env = dict(os.environ, HOME=home, XDG_CACHE_HOME=os.path.join(home, ".cache"),
               XDG_CONFIG_HOME=os.path.join(home, ".config"),
               XDG_DATA_HOME=os.path.join(home, ".local", "share"),
               XDG_RUNTIME_DIR=home, MESA_SHADER_CACHE_DIR=os.path.join(home, "mesa"),
               FRAMEFIX_TEST_OUT=os.path.abspath(args.out))
    xvfb = None
    if args.gui:
        xvfb, env["DISPLAY"] = start_xvfb(env)
        env["QTWEBENGINE_DISABLE_SANDBOX"] = "1"
    try:
        proc = subprocess.Popen(command, env=env, start_new_session=True)
        try:
            code = proc.wait(timeout=args.timeout)
        except subprocess.TimeoutExpired:
            print("run_freecad: timed out after %.0f s" % args.timeout, file=sys.stderr)
            code = 124
        try:
            os.killpg(proc.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    finally:
        if xvfb is not None:
            xvfb.terminate()
            xvfb.wait()
        shutil.rmtree(home, ignore_errors=True)
    return code


if __name__ == "__main__":
    sys.exit(main())
