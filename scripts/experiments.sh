#!/usr/bin/env bash
# Builds the paper's experiments (experiments/fig*.cpp), runs each into OUT/figN (default
# ./experiment-output) and renders their plots (scripts/plot_csv.py, matplotlib) into OUT/plots.
#
#   bash scripts/experiments.sh [--build-dir DIR] [--out DIR] [--no-build] [--docs]
#
# --docs also copies the plots to docs/results/ (the figures docs/RESULTS.md embeds).
# Exit 1 when an experiment fails or a plot cannot be drawn; the others still run.
set -euo pipefail
cd "$(dirname "$0")/.."

build=build
out=experiment-output
do_build=1
docs=0
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --no-build) do_build=0; shift ;;
    --docs) docs=1; shift ;;
    -h|--help) sed -n '2,8p' "$0"; exit 0 ;;
    *) echo "experiments.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done

programs=()
for src in experiments/fig*.cpp; do programs+=("$(basename "$src" .cpp)"); done

if [ "$do_build" = 1 ]; then
  bash scripts/install-deps.sh
  if [ ! -f "$build/CMakeCache.txt" ]; then cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >&2; fi
  cmake --build "$build" -j "${JOBS:-$(nproc)}" --target "${programs[@]}" >&2
fi

status=0
for p in "${programs[@]}"; do
  fig=${p%%_*}   # fig2_degree8_vertex -> fig2
  exe="$build/experiments/$p"
  if [ ! -x "$exe" ]; then
    echo "experiments.sh: $exe is not built" >&2; status=1; continue
  fi
  echo "== $p -> $out/$fig" >&2
  mkdir -p "$out/$fig"
  start=$(date +%s%N)
  if "$exe" --out "$out/$fig" > "$out/$fig/run.log" 2>&1; then
    echo "   ok ($(( ($(date +%s%N) - start) / 1000000 )) ms; stdout and stderr in $out/$fig/run.log)" >&2
  else
    echo "   FAILED: see $out/$fig/run.log" >&2; status=1
  fi
done

# A python with matplotlib: the first python3 on PATH, else Debian's.
py=""
for cand in python3 /usr/bin/python3; do
  if command -v "$cand" >/dev/null && "$cand" -c 'import matplotlib' 2>/dev/null; then py=$cand; break; fi
done
if [ -z "$py" ]; then
  echo "experiments.sh: no python3 with matplotlib (apt-get install python3-matplotlib): plots skipped" >&2
  exit 1
fi

mkdir -p "$out/plots"
# plot NAME CSV ARGS...: skipped (not an error) when the experiment's CSV is absent.
plot() {
  local name=$1 csv=$2; shift 2
  [ -f "$csv" ] || { echo "   (no $csv: $name skipped)" >&2; return 0; }
  if "$py" scripts/plot_csv.py "$csv" "$@" -o "$out/plots/$name.svg"; then
    echo "   plot $out/plots/$name.svg" >&2
  else
    status=1
  fi
}

echo "== plots" >&2
plot fig2_dof "$out/fig2/fig2_dof_sweep.csv" --x max_fold_angle_deg \
  --y dof_library,dof_fd_svd,dof_fd_lu,paper_dof \
  --labels "library (analytic Jacobian)","finite-difference Eq. 1 (SVD)","finite-difference Eq. 1 (LU)","paper" \
  --xlabel "largest fold angle of the state (°)" --ylabel "DOF" --title "Fig. 2: degree-8 vertex, DOF from flat to folded"
plot fig2_sigma3 "$out/fig2/fig2_dof_sweep.csv" --x max_fold_angle_deg --y sigma3_over_sigma1 --logx --logy \
  --labels "σ3/σ1 of the Eq. 1 Jacobian" --xlabel "largest fold angle of the state (°)" --ylabel "σ3 / σ1" \
  --title "Fig. 2: the third crease axis leaves the plane linearly"
plot fig3_boat_angles "$out/fig3/fig3_boat.csv" --x driven_deg \
  --y j1_bow_keel,j2_keel_AC_driven,j3_keel_CB,j4_stern_keel,j5_diag_A_up,j6_diag_A_down,j7_transverse_C_up,j8_transverse_C_down,j9_diag_B_up,j10_diag_B_down \
  --labels "1 bow keel","2 keel A–C (driven)","3 keel C–B","4 stern keel","5 diagonal at A","6 diagonal at A","7 transverse at C","8 transverse at C","9 diagonal at B","10 diagonal at B" \
  --xlabel "driven crease: keel A–C (°)" --ylabel "fold angle (°)" --title "Fig. 3: the boat follows one actuated crease"
plot fig3_boat_closure "$out/fig3/fig3_boat.csv" --x driven_deg --y closure_error_rad,closed_form_error_deg --logy \
  --labels "closure error (rad)","diagonals vs closed form (°)" --xlabel "driven crease: keel A–C (°)" --ylabel "error" \
  --title "Fig. 3: closure along the projected path"
plot fig4_corner_cube "$out/fig4/fig4_corner_cube.csv" --x frame \
  --y joint1_deg,joint2_deg,joint3_deg,joint4_deg,joint5_deg --labels "crease 1","crease 2","crease 3","crease 4","crease 5" \
  --xlabel "frame of the unfolding (Carpenter's rule step; the folding replays it backwards)" --ylabel "fold angle (°)" \
  --title "Fig. 4: corner cube unfolded by expansive motions"
plot fig67_straight "$out/fig67/fig67_straight.csv" --x t --y closure_residual_rad \
  --labels "largest loop residual" --xlabel "t (every crease at t × its bird-base angle)" --ylabel "closure residual (rad)" \
  --title "Figs. 6/7: all creases at once is not a rigid folding"
plot fig67_rigid_path "$out/fig67/fig67_rigid_path.csv" --x step --y diff_crossing_free_deg,diff_crossing_deg --logy \
  --labels "no facets crossing","facets crossing (simulator)" --xlabel "closed state along the rigid folding" \
  --ylabel "largest crease difference to the target (°)" --title "Figs. 6/7: rigid folding toward the bird base"
plot fig10_beam "$out/fig10/fig10_beam.csv" --x case --y tip_mm,paper_mm --labels "ours","paper" \
  --ylabel "tip deflection under 40 N (mm)" --title "Fig. 10: the 2×4 cube beam"

if [ "$docs" = 1 ]; then
  mkdir -p docs/results
  for f in "$out"/plots/*.svg "$out"/fig67/fig7_frame_*.svg "$out"/fig67/birdbase.svg "$out"/fig5a/fig5a_event_*.svg; do
    [ -f "$f" ] && cp "$f" docs/results/
  done
  echo "== copied the plots to docs/results/" >&2
fi
exit $status
