# Sourced by the scripts that compare two builds (compare_builds.sh,
# compare_instructions.sh) once OLD and NEW are set: each refused unless it
# holds a built sweep program, then made absolute (workspace.sh moves to the
# repository root); then NEW's workspace (workspace.sh: the sweep finds
# aurora_config through its package path).
for side in OLD NEW; do
  b=${!side}
  [ -x "$b/devel/lib/aurora_sweep/sweep" ] || { echo "no sweep program in $b/devel/lib/aurora_sweep/ (build it first)" >&2; exit 2; }
  printf -v "$side" '%s' "$(realpath "$b")"
done
BUILD=$NEW
source "$(dirname "${BASH_SOURCE[0]}")/workspace.sh"
