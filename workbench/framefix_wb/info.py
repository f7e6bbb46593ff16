"""`framefix info`: what the backend offers (correction and block methods, sizing constants).

One JSON object on stdout, version 1. Like report.json it comes from a child process that
may be old, broken or not a framefix at all: it is checked here, once, and anything else
becomes a BackendError saying the backend does not answer `info`. InfoJob has the interface
runner.run_sync drives (argv, env, timeout, add_line, finish, timeout_error, cleanup).
"""
import json
import math

from .errors import BackendError

INFO_TIMEOUT_S = 10.0  # `info` answers at once; a backend that hangs must not hold a panel long
MAX_TEXT = 65536  # output kept: a flood must stay cheap


def _fail(what):
    raise BackendError("the backend's `framefix info` is unusable: " + what, "info")


def _method(m, i):
    if not isinstance(m, dict) or not isinstance(m.get("name"), str) or not m["name"]:
        _fail("correction_methods[%d].name is not a name" % i)
    if not isinstance(m.get("available"), bool):
        _fail("correction_methods[%d].available is not true or false" % i)
    return {"name": m["name"], "available": m["available"],
            "description": str(m.get("description") or "")}


def check_info(data):
    """The parts of `framefix info` the workbench uses, checked; raises BackendError."""
    if not isinstance(data, dict) or data.get("version") != 1:
        _fail("version is %r, this workbench reads version 1"
              % (data.get("version") if isinstance(data, dict) else data))
    tets, volume = data.get("default_target_tets"), data.get("mean_tet_volume_h3")
    if not isinstance(tets, int) or tets <= 0:
        _fail("default_target_tets is not a positive integer")
    if not isinstance(volume, (int, float)) or not math.isfinite(volume) or volume <= 0:
        _fail("mean_tet_volume_h3 is not a positive number")
    methods = data.get("correction_methods")
    if not isinstance(methods, list) or not methods:
        _fail("correction_methods is not a list of methods")
    blocks = data.get("block_methods")
    if not isinstance(blocks, list) or not blocks or not all(
            isinstance(b, str) and b for b in blocks):
        _fail("block_methods is not a list of names")
    return {"default_target_tets": tets, "mean_tet_volume_h3": float(volume),
            "correction_methods": [_method(m, i) for i, m in enumerate(methods)],
            "block_methods": list(blocks)}


def parse_info(text):
    """check_info of the first JSON object in `text` (stderr noise before it is skipped)."""
    start = text.find("{")
    if start < 0:
        _fail("it printed no JSON object")
    try:
        data, _ = json.JSONDecoder().raw_decode(text[start:])
    except ValueError as e:
        _fail("not valid JSON (%s)" % e)
    return check_info(data)


class InfoJob:
    """`<backend> info`, run by runner.run_sync."""

    def __init__(self, backend, timeout=INFO_TIMEOUT_S):
        self.argv = backend.argv + ["info"]
        self.env = backend.environment()
        self.timeout = timeout
        self.text = ""

    def add_line(self, line):
        if len(self.text) < MAX_TEXT:
            self.text += line
        return None  # no progress lines

    def finish(self, exit_code, crashed=False, signal_number=None):
        if crashed or exit_code != 0:
            last = [l for l in self.text.splitlines() if l.strip()][-1:] or ["no message"]
            raise BackendError(
                "the backend does not answer `framefix info` (exit code %s: %s); it may be "
                "older than this workbench: update it" % (exit_code, last[0][:300]), "info")
        return parse_info(self.text)

    def timeout_error(self):
        return BackendError("the backend did not answer `framefix info` within %.0f s"
                            % self.timeout, "info")

    def cleanup(self):
        pass
