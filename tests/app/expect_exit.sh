#!/usr/bin/env bash
# expect_exit.sh CODE REGEX COMMAND...  — runs COMMAND, passes iff it exits with CODE and
# its combined output matches the extended regular expression REGEX.
set -u
expected=$1 regex=$2
shift 2
output=$("$@" 2>&1)
code=$?
printf '%s\n' "$output"
if [ "$code" -ne "$expected" ]; then
  echo "expect_exit: exit code $code, expected $expected" >&2
  exit 1
fi
if ! printf '%s\n' "$output" | grep -Eq -- "$regex"; then
  echo "expect_exit: output does not match /$regex/" >&2
  exit 1
fi
