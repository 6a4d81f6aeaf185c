#!/bin/bash
# `twinray check-bsdf` on one example of examples/shader_bsdfs (issue 16):
#   check_bsdf.sh TWINRAY FILE.glsl EXPECTED_STATUS [REGEX [ARGS...]]
# runs the verb at 20000 chi-square draws per incident direction (overall significance 0.01,
# Sidak-corrected over every statistical test), checks the exit status, and for a broken example
# that the output names the failing case (REGEX, matched against the FAILED lines; for a passing
# run, against every line).
set -u
twinray=$1
file=$2
expected=$3
pattern=${4:-}
shift 3
[ $# -gt 0 ] && shift
out=$(mktemp)
json=$(mktemp --suffix=.json)
trap 'rm -f "$out" "$json"' EXIT
"$twinray" check-bsdf "$file" --samples 20000 --json "$json" "$@" >"$out" 2>&1
status=$?
cat "$out"
if [ "$status" != "$expected" ]; then
  echo "check_bsdf.sh: $file exited with $status, expected $expected"
  exit 1
fi
if [ -n "$pattern" ] && [ "$expected" != 0 ] && ! grep '^FAILED' "$out" | grep -Eq "$pattern"; then
  echo "check_bsdf.sh: no FAILED line of $file matches '$pattern'"
  exit 1
fi
if [ -n "$pattern" ] && [ "$expected" = 0 ] && ! grep -Eq "$pattern" "$out"; then
  echo "check_bsdf.sh: no line of $file's report matches '$pattern'"
  exit 1
fi
if ! python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); sys.exit(0 if d["passed"] == (sys.argv[2] == "0") and d["checks"] else 1)' "$json" "$expected"; then
  echo "check_bsdf.sh: the JSON report disagrees with the exit status"
  exit 1
fi
echo "check_bsdf.sh: ok"
