#!/usr/bin/env bash
# Grades a class on a Slurm cluster: a job array grades one shard of the submissions per task
# (grader batch --shard K/N), then a job that depends on the whole array merges the shards'
# gradebooks (grader merge).
#
#   grader/slurm/grade-class.sh SUBMISSIONS OUT [SHARDS] [sbatch options...]
#
# SUBMISSIONS is a folder of submissions on a file system every node sees; OUT gets
# shard-K/ per task and, once all are done, OUT/gradebook.csv and OUT/summary.html.
# PATHLAB_BUILD names the PathLab build to grade with (default: build/ beside this script's
# kit), also on a shared file system. Each task asks for PATHLAB_CPUS cores (default 4): one is
# kept for timed runs, the others grade.
#
# What is graded, as `grader batch` takes it (exported to every task; the merge reads the rubric
# and scenes each shard was graded under from its batch.json, and takes the deadline and times):
#   PATHLAB_RUBRIC    the rubric (default: grader/rubric.json of the build's kit)
#   PATHLAB_SCENES    the hidden scenes (default: the kit's grader/hidden_scenes/ when it holds
#                     any; "none" for none)
#   PATHLAB_VARIANT_SEED  where there are no hidden scenes, the seed of the variants of the
#                     public scenes every shard grades on (default: a new one, written to
#                     OUT/variant-seed; keep it from the students)
#   PATHLAB_DEADLINE  flags later submissions as late (e.g. 2026-12-01T23:59)
#   PATHLAB_TIMES     a CSV of id,submitted_at from your LMS
#   PATHLAB_OPTIONS   any other options of grader batch (e.g. "--no-speed")
# Each shard runs the canary and measures the hidden scenes' references itself (about a minute).
set -euo pipefail
if [ $# -lt 2 ]; then
    echo "usage: $0 SUBMISSIONS OUT [SHARDS] [sbatch options...]" >&2
    exit 2
fi
submissions=$(realpath "$1")
out=$(realpath -m "$2")
shards=${3:-8}
shift $(( $# >= 3 ? 3 : 2 ))
here=$(dirname "$(realpath "$0")")
build=$(realpath "${PATHLAB_BUILD:-$here/../../build}")
cpus=${PATHLAB_CPUS:-4}
[ -x "$build/grader" ] || { echo "$0: no grader in $build (set PATHLAB_BUILD)" >&2; exit 2; }
# Paths as every node sees them; a wrong one fails here, before anything is queued.
for name in PATHLAB_RUBRIC PATHLAB_TIMES; do
    if [ -n "${!name:-}" ]; then
        [ -f "${!name}" ] || { echo "$0: $name=${!name} is not a file" >&2; exit 2; }
        export "$name=$(realpath "${!name}")"
    fi
done
if [ -n "${PATHLAB_SCENES:-}" ] && [ "$PATHLAB_SCENES" != none ]; then
    [ -d "$PATHLAB_SCENES" ] || { echo "$0: PATHLAB_SCENES=$PATHLAB_SCENES is not a folder" >&2; exit 2; }
    export PATHLAB_SCENES=$(realpath "$PATHLAB_SCENES")
fi
mkdir -p "$out"
# Every shard must grade on the same variants of the public scenes: one seed for all, kept.
if [ -z "${PATHLAB_VARIANT_SEED:-}" ]; then
    if [ -s "$out/variant-seed" ]; then
        PATHLAB_VARIANT_SEED=$(cat "$out/variant-seed")
    else
        PATHLAB_VARIANT_SEED=$(( ($(od -An -N6 -tu8 /dev/urandom) % 281474976710655) + 1 ))
        echo "$PATHLAB_VARIANT_SEED" > "$out/variant-seed"
    fi
fi
export PATHLAB_VARIANT_SEED

array=$(sbatch --parsable --array="0-$((shards - 1))" --cpus-per-task="$cpus" \
    --job-name=pathlab-grade --output="$out/slurm-%A_%a.log" "$@" \
    --export=ALL,PATHLAB_BUILD="$build" \
    "$here/grade-shard.sbatch" "$submissions" "$out")
merge=$(sbatch --parsable --dependency="afterany:$array" --job-name=pathlab-merge \
    --output="$out/slurm-merge-%j.log" "$@" --export=ALL,PATHLAB_BUILD="$build" \
    "$here/merge.sbatch" "$out" "$shards")
echo "submitted: grading array $array ($shards shards), merge $merge; results in $out"
