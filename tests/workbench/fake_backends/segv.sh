#!/bin/sh
# Fake backend that crashes like a segfaulting mesher, after some progress.
echo "progress load 0.50" >&2
echo "fake backend: about to crash" >&2
kill -SEGV $$
