#!/bin/sh
# Fake backend that hangs, in a grandchild too: timeout and cancel must kill them all.
# FAKE_BACKEND_PIDFILE (if set) gets the pids of both, for the test to check they are gone.
echo "progress load 0.10" >&2
sleep 3600 &
[ -n "$FAKE_BACKEND_PIDFILE" ] && echo "$$ $!" > "$FAKE_BACKEND_PIDFILE"
wait
