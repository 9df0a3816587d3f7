# Sourced by the scripts that compare two builds (compare_builds.sh,
# compare_instructions.sh) once OLD, NEW and SWEEP (the sweep file given,
# or empty) are set: each build refused unless it holds a built sweep
# program, the sweep file unless it is a file; all made absolute
# (workspace.sh moves to the repository root); then NEW's workspace
# (workspace.sh: the sweep finds aurora_config through its package path).
for side in OLD NEW; do
  b=${!side}
  [ -x "$b/devel/lib/aurora_sweep/sweep" ] || { echo "no sweep program in $b/devel/lib/aurora_sweep/ (build it first)" >&2; exit 2; }
  printf -v "$side" '%s' "$(realpath "$b")"
done
if [ -n "$SWEEP" ]; then
  [ -f "$SWEEP" ] || { echo "no sweep file '$SWEEP'" >&2; exit 2; }
  SWEEP=$(realpath "$SWEEP")
fi
BUILD=$NEW
source "$(dirname "${BASH_SOURCE[0]}")/workspace.sh"
