#!/usr/bin/env bash
# Long renders never lose work (issue 12). usage: resume.sh TWINRAY BACKEND SCENE
#  - a render killed with SIGKILL at a random moment after its first checkpoint, then resumed
#    from its last checkpoint, gives the uninterrupted render's image and variance bit for bit;
#  - SIGINT finishes the pass in flight, writes outputs stating their true spp, exits 7, and
#    its checkpoint resumes to the same image;
#  - a checkpoint of another seed or scene, or a damaged one, is refused with exit 8.
set -u
export LC_ALL=C
twinray=$1 backend=$2 scene=$3
spp=${RESUME_SPP:-512}
dir=$(mktemp -d)
trap 'kill -9 $(jobs -p) 2>/dev/null; rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
args=(render "$scene" -D width=64 -D height=64 --spp "$spp" --seed 7 --backend "$backend")
render() { "$twinray" "${args[@]}" "$@"; }
same() {  # pixel data of two EXRs identical (differences > 0 fail)
  oiiotool "$1" "$2" --fail 0 --warn 0 --diff >"$dir/diff.txt" 2>&1 ||
    { cat "$dir/diff.txt"; fail "$1 and $2 differ"; }
}
wait_for() {  # a file to appear while process $2 runs
  while [ ! -s "$1" ]; do kill -0 "$2" 2>/dev/null || return 1; sleep 0.05; done
}

render -o "$dir/full.exr" >"$dir/full.log" 2>&1 || { cat "$dir/full.log"; fail "full render"; }

# SIGKILL at a random moment after the first checkpoint.
"$twinray" "${args[@]}" -o "$dir/killed.exr" --checkpoint 0.3 >"$dir/killed.log" 2>&1 &
pid=$!
wait_for "$dir/killed.checkpoint" "$pid" || fail "render ended before its first checkpoint"
sleep "0.$((RANDOM % 5))"
kill -9 "$pid" 2>/dev/null
wait "$pid" 2>/dev/null
[ ! -e "$dir/killed.exr" ] || fail "the render finished before it was killed"
echo "killed after $(head -c 200 "$dir/killed.checkpoint" | grep -a '^samples') of $spp"
render -o "$dir/killed.exr" --resume "$dir/killed.checkpoint" >"$dir/resumed.log" 2>&1 ||
  { cat "$dir/resumed.log"; fail "resume"; }
same "$dir/full.exr" "$dir/killed.exr"
same "$dir/full_var.exr" "$dir/killed_var.exr"

# SIGINT: outputs with the true sample count, exit 7, resumable.
"$twinray" "${args[@]}" -o "$dir/int.exr" --checkpoint 0.3 >"$dir/int.log" 2>&1 &
pid=$!
wait_for "$dir/int.checkpoint" "$pid" || fail "render ended before its first checkpoint"
kill -INT "$pid"
wait "$pid"
status=$?
[ "$status" = 7 ] || { cat "$dir/int.log"; fail "SIGINT: exit $status, expected 7"; }
done_spp=$(oiiotool --info -v "$dir/int.exr" | sed -n 's/.*twinray:spp: "\([0-9]*\)".*/\1/p')
[ -n "$done_spp" ] && [ "$done_spp" -lt "$spp" ] ||
  fail "interrupted image states spp '$done_spp', expected fewer than $spp"
grep -q "samples $done_spp" <(head -c 300 "$dir/int.checkpoint" | tr -d '\0') ||
  fail "checkpoint does not hold the image's $done_spp spp"
render -o "$dir/int.exr" --resume "$dir/int.checkpoint" >"$dir/int2.log" 2>&1 ||
  { cat "$dir/int2.log"; fail "resume after SIGINT"; }
same "$dir/full.exr" "$dir/int.exr"

# Refusals: exit 8, one line naming what differs; nothing written.
check_refused() {  # expected-substring, render arguments...
  local want=$1
  shift
  render -o "$dir/refused.exr" "$@" >"$dir/refused.log" 2>&1
  local s=$?
  [ "$s" = 8 ] || { cat "$dir/refused.log"; fail "exit $s, expected 8 ($want)"; }
  grep -q "$want" "$dir/refused.log" || { cat "$dir/refused.log"; fail "message lacks '$want'"; }
  [ ! -e "$dir/refused.exr" ] || fail "an image was written for a refused checkpoint"
}
sed -i 's/^seed 7$/seed 8/' "$dir/killed.checkpoint"
check_refused "its seed is '8', this render's is '7'" --resume "$dir/killed.checkpoint"
sed -i 's/^seed 8$/seed 7/' "$dir/killed.checkpoint"
check_refused "its scene is" --resume "$dir/killed.checkpoint" -D max_depth=3
head -c 1000 "$dir/killed.checkpoint" >"$dir/truncated.checkpoint"
check_refused "truncated" --resume "$dir/truncated.checkpoint"
check_refused "not a twinray checkpoint" --resume "$dir/full.exr"
echo "resume.sh ($backend): pass"
