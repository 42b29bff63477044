#!/usr/bin/env bash
# Writes a corpus of the CLI's outputs (generated patterns, folds, plans in every space, the
# fallbacks, Carpenter's rule and Hamiltonian paths; their JSON without wall-clock keys) into
# OUT, so that a refactoring can be checked to change no byte (issue 37's rule):
#   scripts/output-corpus.sh build/apps/foldkit /tmp/before     # on the old commit
#   scripts/output-corpus.sh build/apps/foldkit /tmp/after      # on the new one
#   diff -r /tmp/before /tmp/after                              # nothing but *.err (timings)
# Takes about 10 s (Release). Same seed, same output: two runs of one build compare equal.
set -uo pipefail
if [[ $# -ne 2 ]]; then
  echo "usage: scripts/output-corpus.sh FOLDKIT OUT" >&2
  exit 2
fi
F=$(realpath "$1")
OUT=$2
rm -rf "$OUT" && mkdir -p "$OUT" && cd "$OUT" || exit 2

# The JSON on stdout without its wall-clock keys (seconds, time): those differ run to run.
strip_times() {
  python3 -c '
import json, sys
def s(x):
    if isinstance(x, dict): return {k: s(v) for k, v in x.items() if k not in ("time", "seconds")}
    if isinstance(x, list): return [s(v) for v in x]
    return x
text = sys.stdin.read()
print(json.dumps(s(json.loads(text)), sort_keys=True) if text.strip() else "")'
}
# run NAME ARGS…: stdout (JSON) to NAME.json, stderr and the exit code to NAME.err.
run() {
  local name=$1
  shift
  "$F" "$@" --json 2>"$name.err" | strip_times >"$name.json"
  echo "exit ${PIPESTATUS[0]}" >>"$name.err"
}

"$F" generate single-vertex --sectors 50,40,50,40,50,40,50,40 -o sv.pmml 2>/dev/null
"$F" generate miura --rows 4 --cols 4 -o miura.pmml 2>/dev/null
"$F" generate waterbomb --units 2 --rows 2 -o wb.pmml 2>/dev/null
"$F" generate strip -o strip.pmml 2>/dev/null
run miura-fold fold miura.pmml --fraction 0.6 -o miura-fold.cmml
run miura-fold3 fold miura.pmml --fraction 0.3 -o miura-fold3.cmml
run sv-fold fold sv.pmml --velocity 1:1,2:1,3:-1,4:1 --fraction 0.5 -o sv-fold.cmml
run wb-fold fold wb.pmml --fraction 0.4 -o wb-fold.cmml
for space in auto driving projected atlas; do
  run "miura-$space" plan miura.pmml --goal miura-fold.cmml --space "$space" --time 10 -o "miura-$space.cmml"
done
run miura-tangent-bundle plan miura.pmml --goal miura-fold3.cmml --space tangent-bundle --time 2 -o miura-tangent-bundle.cmml
for space in auto single-vertex projected; do
  run "sv-$space" plan sv.pmml --goal sv-fold.cmml --space "$space" --time 10 -o "sv-$space.cmml"
done
run wb-auto plan wb.pmml --goal wb-fold.cmml --time 10 -o wb-auto.cmml
run miura-rrt plan miura.pmml --goal miura-fold.cmml --no-fallback --planner RRT --seed 3 --time 10 -o miura-rrt.cmml
run sv-carpenter-fallback plan sv.pmml --start sv-fold.cmml --goal-angles 1:-20,2:-20 --time 10 -o sv-carpenter-fallback.cmml
run miura-from-folded plan miura.pmml --start miura-fold3.cmml --goal miura-fold.cmml --time 10 -o miura-from-folded.cmml
run strip-no-loops plan strip.pmml --goal-angles 1:30 --time 10 -o strip.cmml
run sv-dof dof sv.pmml
run sv-project project sv.pmml --state sv-fold.cmml --speed 45 -o sv-project.cmml
run sv-flatten carpenter sv.pmml --state sv-fold.cmml -o sv-flatten.cmml
printf '0 0\n1 0\n1 1\n0 1\n0 2\n2 2\n2 -1\n' >chain.txt
run chain-straighten carpenter chain.txt -o chain.json
printf '####\n#..#\n####\n' >shape.txt
run shape-hamiltonian hamiltonian shape.txt -o shape.path
run shape-refined hamiltonian shape.txt --refine -o shape-refined.path
echo "output-corpus: $(ls | wc -l) files in $OUT" >&2
