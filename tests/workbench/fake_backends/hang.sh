#!/bin/sh
# Fake backend that hangs (in a grandchild too): the runner's timeout must kill them all.
echo "progress load 0.10" >&2
sleep 3600 &
sleep 3600
