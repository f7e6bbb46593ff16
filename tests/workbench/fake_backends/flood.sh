#!/bin/sh
# Fake backend that floods its output (many lines, then megabytes without a newline) and
# exits 0 without a report: the runners must stay cheap and report the missing report.
yes "progress mesh 0.5 garbage garbage garbage" | head -n 200000 >&2
head -c 20000000 /dev/zero | tr '\0' 'x' >&2
exit 0
