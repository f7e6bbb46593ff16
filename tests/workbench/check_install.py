#!/usr/bin/python3
"""The one install command works: `cmake --install BUILD --prefix <HOME>/.local/share/FreeCAD/
Mod/FrameFix` into a throw-away HOME, then a plain FreeCAD (no -M) in that HOME loads the
workbench, finds the backend installed beside it and imports framefix.freecad.

    check_install.py BUILD_DIR
"""
import os
import shutil
import subprocess
import sys
import tempfile

CHECK = os.path.join(os.path.dirname(os.path.abspath(__file__)), "ffcheck_installed.py")


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
        p = subprocess.run(["freecadcmd", CHECK], env=env, timeout=600, cwd=home,
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        lines = [l for l in p.stdout.splitlines() if l.startswith("check")]
        print("\n".join(lines))
        return 0 if p.returncode == 0 and lines and "check: all ok" in lines[-1] else 1
    finally:
        shutil.rmtree(home, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
