#!/usr/bin/env bash
# expect-failure.sh DIR REGEX CMD...: run CMD in DIR; pass only if it exits
# non-zero (within the ctest timeout: no hang) AND its output matches REGEX
# (extended, case-sensitive). Prints the output either way. With
# EXPECT_RC=<n> in the environment the exit code must be exactly n.
set -uo pipefail
dir=$1 regex=$2; shift 2
out=$(cd "$dir" && PWD="$dir" "$@" 2>&1); rc=$?
printf '%s\n' "$out" | tail -n 30
if [ $rc -eq 0 ]; then echo "expect-failure: '$*' succeeded but should have failed" >&2; exit 1; fi
if [ -n "${EXPECT_RC:-}" ] && [ "$rc" -ne "$EXPECT_RC" ]; then
  echo "expect-failure: exit $rc, expected exit $EXPECT_RC" >&2; exit 1
fi
if ! printf '%s\n' "$out" | grep -Eq -- "$regex"; then
  echo "expect-failure: exit $rc as expected, but the output does not match /$regex/" >&2; exit 1
fi
echo "expect-failure: exit $rc with /$regex/ as expected"
