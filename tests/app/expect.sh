#!/usr/bin/env bash
# expect.sh CODE REGEX -- COMMAND...: runs COMMAND, passes if it exits with CODE and its combined
# output matches REGEX (extended grep). Used by the CLI tests in tests/CMakeLists.txt.
code=$1; regex=$2; shift 3
out=$("$@" 2>&1); got=$?
echo "$out"
[ "$got" -eq "$code" ] || { echo "expect.sh: exit code $got, expected $code"; exit 1; }
grep -Eq -- "$regex" <<<"$out" || { echo "expect.sh: output does not match /$regex/"; exit 1; }
