#!/bin/sh
# Fake backend that rejects its input the way the CLI does (exit 2, one-line message).
echo "progress load 0.00" >&2
echo "framefix: error [load]: shape has 2 solids; select one solid" >&2
exit 2
