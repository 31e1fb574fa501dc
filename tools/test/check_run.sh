#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs a command and checks its exit status, its output (standard output and
# standard error together) and the files it leaves behind.
#
# usage: check_run.sh [checks...] -- COMMAND [ARGUMENTS...]
#   --status success|failure|N   expected exit status (failure: any non-zero)
#   --expect REGEX               the output must match REGEX (grep -E), repeatable
#   --reject REGEX               the output must not match REGEX, repeatable
#   --count REGEX N              exactly N lines of the output match REGEX, repeatable
#   --absent FILE                FILE must not exist afterwards (removed before the run)
#   --exists FILE                FILE must exist afterwards (removed before the run)
#   --remove FILE                FILE is removed before the run
#   --corrupt FROM TO            TO is a copy of FROM with a byte flipped in the middle
set -u
status=success
expects=() rejects=() absents=() exists=() counts=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
  case "$1" in
    --status) status="$2"; shift 2 ;;
    --expect) expects+=("$2"); shift 2 ;;
    --reject) rejects+=("$2"); shift 2 ;;
    --count) counts+=("$2" "$3"); shift 3 ;;
    --absent) absents+=("$2"); rm -f "$2"; shift 2 ;;
    --exists) exists+=("$2"); rm -f "$2"; shift 2 ;;
    --remove) rm -f "$2"; shift 2 ;;
    --corrupt)
      cp "$2" "$3" || exit 1
      size=$(stat -c %s "$3")
      offset=$((size / 2))
      byte=$(od -An -tu1 -j "$offset" -N1 "$3" | tr -d ' ')
      printf "$(printf '\\%03o' $(( (byte + 1) % 256 )))" |
        dd of="$3" bs=1 seek="$offset" conv=notrunc status=none || exit 1
      shift 3 ;;
    *) echo "check_run.sh: unknown check '$1'" >&2; exit 2 ;;
  esac
done
[ "${1:-}" = "--" ] || { echo "check_run.sh: missing -- COMMAND" >&2; exit 2; }
shift

output=$("$@" 2>&1)
code=$?
printf '%s\n' "$output"
echo "[exit status $code]"

failed=0
case "$status" in
  success) [ $code -eq 0 ] || { echo "FAILED: expected exit status 0"; failed=1; } ;;
  failure) [ $code -ne 0 ] || { echo "FAILED: expected a non-zero exit status"; failed=1; } ;;
  *) [ $code -eq "$status" ] || { echo "FAILED: expected exit status $status"; failed=1; } ;;
esac
# A crash is never the expected failure.
if [ $code -ge 128 ]; then echo "FAILED: killed by signal $((code - 128))"; failed=1; fi
for regex in "${expects[@]+"${expects[@]}"}"; do
  grep -Eq -- "$regex" <<<"$output" || { echo "FAILED: the output does not match: $regex"; failed=1; }
done
for regex in "${rejects[@]+"${rejects[@]}"}"; do
  if grep -Eq -- "$regex" <<<"$output"; then echo "FAILED: the output matches: $regex"; failed=1; fi
done
set -- "${counts[@]+"${counts[@]}"}"
while [ $# -gt 0 ]; do
  found=$(grep -Ec -- "$1" <<<"$output")
  [ "$found" -eq "$2" ] || { echo "FAILED: $found lines match $1, expected $2"; failed=1; }
  shift 2
done
for file in "${absents[@]+"${absents[@]}"}"; do
  [ ! -e "$file" ] || { echo "FAILED: $file was written"; failed=1; }
done
for file in "${exists[@]+"${exists[@]}"}"; do
  [ -s "$file" ] || { echo "FAILED: $file was not written"; failed=1; }
done
exit $failed
