#!/bin/sh
# Usage: [EXPECT_STATUS=N] expect-failure.sh REGEX COMMAND [ARGS...]
# Passes when COMMAND exits with status 1 (a handled error, not a crash or
# signal; or N: 2 is a usage error) and its output matches the extended
# regular expression REGEX.
expected=${EXPECT_STATUS:-1}
regex=$1
shift
output=$("$@" 2>&1)
status=$?
printf '%s\n' "$output"
if [ "$status" -ne "$expected" ]; then
    echo "expect-failure: exit status $status, expected $expected" >&2
    exit 1
fi
if ! printf '%s\n' "$output" | grep -Eq -- "$regex"; then
    echo "expect-failure: output does not match: $regex" >&2
    exit 1
fi
