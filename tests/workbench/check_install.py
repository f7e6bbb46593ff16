#!/usr/bin/python3
"""The one install command works: `cmake --install BUILD --prefix <HOME>/.local/share/FreeCAD/
Mod/FrameFix` into a throw-away HOME, then a plain FreeCAD (no -M) in that HOME loads the
workbench, finds the backend installed beside it and imports framefix.freecad, and the GUI
(under its own Xvfb) lists and activates the workbench.

    check_install.py BUILD_DIR
"""
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from run_freecad import start_xvfb  # noqa: E402


def run_freecad(argv, env, cwd):
    p = subprocess.run(argv, env=env, timeout=600, cwd=cwd, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True)
    lines = [l for l in p.stdout.splitlines() if l.startswith("check") or "Error" in l]
    print("\n".join(lines))
    return p.returncode == 0 and bool(lines) and " ok" in lines[-1]


def main(build):
    home = tempfile.mkdtemp(prefix="framefix_install_")
    try:
        prefix = os.path.join(home, ".local", "share", "FreeCAD", "Mod", "FrameFix")
        subprocess.run(["cmake", "--install", build, "--prefix", prefix], check=True,
                       stdout=subprocess.DEVNULL)
        env = {k: v for k, v in os.environ.items() if not k.startswith("FRAMEFIX_")}
        env.update(HOME=home, XDG_CONFIG_HOME=os.path.join(home, ".config"),
                   XDG_DATA_HOME=os.path.join(home, ".local", "share"),
                   XDG_CACHE_HOME=os.path.join(home, ".cache"))
        ok = run_freecad(["freecadcmd", os.path.join(HERE, "ffcheck_installed.py")], env, home)
        xvfb, env["DISPLAY"] = start_xvfb(env)
        env["QTWEBENGINE_DISABLE_SANDBOX"] = "1"
        try:
            ok = run_freecad(["freecad", os.path.join(HERE, "ffcheck_installed_gui.py")],
                             env, home) and ok
        finally:
            xvfb.terminate()
            xvfb.wait()
        return 0 if ok else 1
    finally:
        shutil.rmtree(home, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
