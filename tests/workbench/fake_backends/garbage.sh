#!/bin/sh
# Fake backend that exits 0 after printing noise and writing a report that is not JSON.
out=""
while [ $# -gt 0 ]; do [ "$1" = "--out" ] && out="$2"; shift; done
echo "progress mesh notanumber" >&2
head -c 300 /dev/urandom | tr -dc 'a-zA-Z0-9 \n' >&2
printf '{"version": 1, "singularities": {"curves": [' > "$out/report.json"
exit 0
