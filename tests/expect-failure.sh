#!/bin/sh
# Usage: expect-failure.sh REGEX COMMAND [ARGS...]
# Passes when COMMAND exits with status 1 (a handled error, not a crash or
# signal) and its output matches the extended regular expression REGEX.
regex=$1
shift
output=$("$@" 2>&1)
status=$?
printf '%s\n' "$output"
if [ "$status" -ne 1 ]; then
    echo "expect-failure: exit status $status, expected 1" >&2
    exit 1
fi
if ! printf '%s\n' "$output" | grep -Eq -- "$regex"; then
    echo "expect-failure: output does not match: $regex" >&2
    exit 1
fi
