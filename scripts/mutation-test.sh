#!/bin/sh
# Mutation testing of the fast tests: applies each mutation of scripts/mutations.py to a scratch
# copy of the tree, rebuilds incrementally, runs the tests named for it, prints the table and the
# score, exits non-zero below 95%. Options: --list, --check, --only NAME..., --jobs N,
# --timeout S, --workdir DIR (see scripts/mutation_test.py).
root=$(cd "$(dirname "$0")/.." && pwd)
. "$root/scripts/lib/python-path.sh"
exec python3 "$root/scripts/mutation_test.py" "$@"
