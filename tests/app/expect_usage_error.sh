#!/usr/bin/env bash
# Usage: expect_usage_error.sh REGEX PROGRAM [ARGS...]
# Passes when PROGRAM exits with status 2, prints exactly one line on stderr, that line matches
# REGEX (extended), and nothing is written to stdout.
set -u
regex=$1
shift
err=$(mktemp)
out=$(mktemp)
"$@" >"$out" 2>"$err"
status=$?
lines=$(wc -l <"$err")
msg=$(cat "$err")
rm -f "$err"
stdout_bytes=$(wc -c <"$out")
rm -f "$out"
echo "exit status: $status; stderr: $msg"
[ "$status" -eq 2 ] || { echo "FAIL: expected exit status 2"; exit 1; }
[ "$lines" -eq 1 ] || { echo "FAIL: expected exactly one line on stderr, got $lines"; exit 1; }
[ "$stdout_bytes" -eq 0 ] || { echo "FAIL: expected nothing on stdout"; exit 1; }
echo "$msg" | grep -Eq -- "$regex" || { echo "FAIL: message does not match /$regex/"; exit 1; }
echo "ok"
