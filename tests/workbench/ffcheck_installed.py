# Run by check_install.py as `freecadcmd ffcheck_installed.py` in a HOME holding only the
# installed workbench. freecadcmd imports scripts as modules and reruns raising ones: every
# outcome ends in os._exit.
import os
import sys
import traceback


def _check():
    import Part
    from framefix_wb.backend import find_backend
    from framefix_wb.paths import icon
    backend = find_backend()
    print("check: backend", backend)
    assert backend.origin.startswith("installed"), backend.origin
    assert os.path.isfile(icon("FrameFix_Analyze")), icon("FrameFix_Analyze")
    import framefix.freecad as ff
    r = ff.analyze(Part.makeBox(1, 1, 1))
    print("check: cube summary", r.summary)
    assert r.summary["curves_3_5"] == 0 and r.meshable, r.summary


try:
    _check()
    print("check: all ok")
    code = 0
except BaseException:
    traceback.print_exc(file=sys.stdout)
    code = 1
sys.stdout.flush()
os._exit(code)
