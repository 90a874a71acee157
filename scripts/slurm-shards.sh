#!/usr/bin/env bash
# Runs part of the suite as a Slurm job array of N shards on a single-node test cluster
# (scripts/slurm-cluster.sh), merges the shards and checks that the merged report says what one
# unsharded run says. Debian 12, as root, after `bash scripts/setup.sh`.
#
#   bash scripts/slurm-shards.sh [N] [PATTERN...]     # default: 3 shards of a fast set of cases
#
# Steps, all in a fresh work folder (printed at the end and left for reading):
#   1. bash scripts/slurm-cluster.sh (installs and starts Slurm when needed);
#   2. groundtruth run PATTERN... --out WORK/unsharded, on this machine;
#   3. sbatch --array=1-N of a job script whose task K runs
#      groundtruth run PATTERN... --shard auto --out WORK/shard-K
#      (--shard auto reads SLURM_ARRAY_TASK_ID/_COUNT/_MIN), then waits for the array;
#   4. every task must have exited 0 or 1 (1: a check failed, which is a result); 2, a signal,
#      a time limit or a cancelled task fails the script;
#   5. groundtruth merge WORK/shard-1 ... WORK/shard-N --out WORK/merged;
#   6. groundtruth diff-reports WORK/unsharded/report.json WORK/merged/report.json --json: no
#      regression, fix, outcome change, added, removed or moved value, and the same cases in
#      both (timings may differ).
# Exit 0 only when all of that holds, 1 otherwise.
#
# Environment:
#   GROUNDTRUTH            the binary (default build/release/groundtruth of this checkout)
#   GT_SLURM_WORK          folder to create the work folder in (default: mktemp -d in $TMPDIR or
#                          /tmp). On a real cluster it must be on a filesystem every node sees.
#   GT_SLURM_JOB_TIMEOUT   seconds to wait for the array (default 1800); also its --time limit
#   GT_SLURM_SBATCH_ARGS   extra sbatch options, split at spaces (e.g. "--partition=gpu --gres=gpu:1")
#   GT_SLURM_SKIP_CLUSTER  1: do not run scripts/slurm-cluster.sh, submit to the cluster sbatch knows
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)

say() { echo "slurm-shards: $*"; }
die() {
  echo "slurm-shards: error: $*" >&2
  exit 1
}
usage() {
  sed -n '2,/^set -euo/p' "$0" | sed -e '$d' -e 's/^# \{0,1\}//'
}

default_patterns=(
  'noise.*'
  'erosion.*.spec.*'
  'erosion.thermal.mutant_probe.cone'
  'mesh.check.*'
  'terrain.*'
  'render.*.mutant_probe.*'
  'cave.marching_tetrahedra.mutant_probe.*'
)

shards=3
case "${1:-}" in
  -h | --help)
    usage
    exit 0
    ;;
  '' | *[!0-9]*) ;;
  *)
    shards=$((10#$1))
    shift
    ;;
esac
[ "$shards" -ge 1 ] || die "N must be at least 1"
if [ $# -gt 0 ]; then patterns=("$@"); else patterns=("${default_patterns[@]}"); fi

job_timeout=${GT_SLURM_JOB_TIMEOUT:-1800}
case "$job_timeout" in '' | *[!0-9]*) die "GT_SLURM_JOB_TIMEOUT must be a whole number of seconds" ;; esac
gt=${GROUNDTRUTH:-$repo/build/release/groundtruth}
[ -x "$gt" ] || die "no groundtruth binary at $gt: run 'bash scripts/setup.sh' first (or set GROUNDTRUTH)"
gt=$(realpath "$gt")
command -v python3 >/dev/null || die "python3 is missing (apt-get install python3)"

# --- 1. the cluster
if [ "${GT_SLURM_SKIP_CLUSTER:-0}" != 1 ]; then
  bash "$repo/scripts/slurm-cluster.sh"
fi
for c in sbatch squeue scontrol scancel; do
  command -v "$c" >/dev/null || die "$c is missing: is Slurm installed (bash scripts/slurm-cluster.sh)?"
done

# --- the work folder
if [ -n "${GT_SLURM_WORK:-}" ]; then
  mkdir -p "$GT_SLURM_WORK"
  work=$(mktemp -d "$(realpath "$GT_SLURM_WORK")/gt-slurm.XXXXXX")
else
  work=$(mktemp -d "${TMPDIR:-/tmp}/gt-slurm.XXXXXX")
fi
chmod 0755 "$work" # tasks may run as another user on a real cluster; here they run as root
mkdir -p "$work/logs" "$work/status"
say "work folder $work; $shards shards of: ${patterns[*]}"
job_id=""
cleanup_job() {
  if [ -n "$job_id" ]; then
    scancel "$job_id" 2>/dev/null || true
    say "cancelled job $job_id"
  fi
}
trap 'cleanup_job; exit 130' INT TERM

# --- 2. the unsharded run
say "unsharded run -> $work/unsharded"
start=$(date +%s)
set +e
(cd "$repo" && "$gt" run "${patterns[@]}" --quiet --out "$work/unsharded") >"$work/logs/unsharded.out" 2>&1
rc=$?
set -e
tail -n 1 "$work/logs/unsharded.out"
case $rc in
  0 | 1) ;;
  *) die "the unsharded run exited $rc (see $work/logs/unsharded.out)" ;;
esac
say "unsharded run took $(($(date +%s) - start)) s (exit $rc)"

# --- 3. the job array
# The job script is written into the work folder so the logs say exactly what ran. Each task
# records groundtruth's exit status in status/task-K.rc; a task killed before that (time limit,
# scancel, a lost node) leaves no such file.
cat >"$work/job.sh" <<'EOF'
#!/usr/bin/env bash
# One task of groundtruth's Slurm job array (written by scripts/slurm-shards.sh).
# Arguments: GROUNDTRUTH WORK PATTERN...
set -uo pipefail
gt=$1 work=$2
shift 2
task=${SLURM_ARRAY_TASK_ID:?run this as a task of a job array (sbatch --array=1-N)}
echo "task $task of $SLURM_ARRAY_TASK_COUNT (array ${SLURM_ARRAY_TASK_MIN}-${SLURM_ARRAY_TASK_MAX}) on $(hostname -s)"
"$gt" run "$@" --shard auto --quiet --out "$work/shard-$task"
rc=$?
echo "$rc" >"$work/status/task-$task.rc.tmp" && mv "$work/status/task-$task.rc.tmp" "$work/status/task-$task.rc"
exit "$rc"
EOF
chmod 0755 "$work/job.sh"

time_limit=$(((job_timeout + 59) / 60))
extra=()
if [ -n "${GT_SLURM_SBATCH_ARGS:-}" ]; then read -r -a extra <<<"$GT_SLURM_SBATCH_ARGS"; fi
start=$(date +%s)
job_id=$(sbatch --parsable --array="1-$shards" --job-name=groundtruth-shards --chdir="$repo" \
  --output="$work/logs/shard-%a.out" --time="$time_limit" ${extra[@]+"${extra[@]}"} \
  "$work/job.sh" "$gt" "$work" "${patterns[@]}") || die "sbatch refused the job array"
job_id=${job_id%%;*}
say "submitted job array $job_id (tasks 1-$shards); waiting up to ${job_timeout}s"

# Wait until squeue no longer lists any task of the array. (sbatch --wait would do, but could not
# be given a timeout that also cancels the job.)
last_note=$start
while :; do
  set +e
  queued=$(squeue -h -j "$job_id" -o '%T' 2>&1)
  qrc=$?
  set -e
  if [ $qrc -eq 0 ] && [ -z "$queued" ]; then break; fi
  if [ $qrc -ne 0 ]; then
    case "$queued" in *"Invalid job id"*) break ;; esac # finished and already purged
  fi
  now=$(date +%s)
  if [ $((now - start)) -ge "$job_timeout" ]; then
    cleanup_job
    die "job array $job_id did not finish within ${job_timeout}s (logs in $work/logs)"
  fi
  if [ $((now - last_note)) -ge 30 ]; then
    if [ $qrc -eq 0 ]; then
      say "after $((now - start)) s: $(printf '%s\n' "$queued" | sort | uniq -c | awk '{printf "%s %s ", $1, tolower($2)}')"
    else
      say "after $((now - start)) s: squeue failed: $queued"
    fi
    last_note=$now
  fi
  sleep 2
done
job_id_done=$job_id
job_id="" # nothing left to cancel
say "job array $job_id_done finished after $(($(date +%s) - start)) s"

# --- 4. every task's exit status
failed=0
for k in $(seq 1 "$shards"); do
  rc_file="$work/status/task-$k.rc"
  slurm_view=$(scontrol -o show job "${job_id_done}_$k" 2>/dev/null | grep -oE '(JobState|Reason|ExitCode)=[^ ]*' |
    paste -sd ' ' || true)
  if [ ! -f "$rc_file" ]; then
    say "task $k: no exit status: it was killed or never ran (${slurm_view:-no record left in slurmctld}); log $work/logs/shard-$k.out"
    failed=1
    continue
  fi
  rc=$(cat "$rc_file")
  case "$rc" in
    0) say "task $k: exit 0" ;;
    1) say "task $k: exit 1 (a check failed or an expectation did not hold: a result, not an engine failure)" ;;
    *)
      if [ "$rc" -gt 128 ] 2>/dev/null; then why="killed by signal $((rc - 128))"; else why="exit $rc"; fi
      say "task $k: FAILED, $why (${slurm_view:-}); log $work/logs/shard-$k.out:"
      tail -n 5 "$work/logs/shard-$k.out" | sed 's/^/    /'
      failed=1
      ;;
  esac
done
[ "$failed" -eq 0 ] || die "some tasks of job array $job_id_done failed; nothing merged (work folder $work)"

# --- 5. merge
shard_dirs=()
for k in $(seq 1 "$shards"); do shard_dirs+=("$work/shard-$k"); done
set +e
"$gt" merge "${shard_dirs[@]}" --out "$work/merged" >"$work/logs/merge.out" 2>&1
rc=$?
set -e
case $rc in
  0 | 1) say "merged $shards shards -> $work/merged (exit $rc)" ;;
  *)
    cat "$work/logs/merge.out" >&2
    die "groundtruth merge exited $rc (work folder $work)"
    ;;
esac

# --- 6. compare with the unsharded run
set +e
"$gt" diff-reports "$work/unsharded/report.json" "$work/merged/report.json" --json >"$work/diff.json" 2>"$work/logs/diff.err"
rc=$?
set -e
if [ $rc -ge 2 ]; then
  cat "$work/logs/diff.err" >&2
  die "groundtruth diff-reports exited $rc (work folder $work)"
fi
set +e
python3 - "$work/diff.json" "$work/unsharded/report.json" "$work/merged/report.json" "$shards" <<'EOF'
import json, sys

diff_file, unsharded_file, merged_file, shards = sys.argv[1:5]
with open(diff_file) as f:
    diff = json.load(f)
with open(unsharded_file) as f:
    unsharded = [c["name"] for c in json.load(f)["cases"]]
with open(merged_file) as f:
    merged = [c["name"] for c in json.load(f)["cases"]]

problems = []
for key in ("regressions", "fixes", "outcome_changes", "added", "removed", "moved"):
    entries = diff.get(key)
    if entries is None:
        problems.append(f"diff-reports --json has no '{key}'")
    elif entries:
        shown = "; ".join(f"{e.get('where')} {e.get('before') or '-'} -> {e.get('after') or '-'}" for e in entries[:5])
        more = f" (+{len(entries) - 5} more)" if len(entries) > 5 else ""
        problems.append(f"{len(entries)} {key.replace('_', ' ')}: {shown}{more}")
if sorted(unsharded) != sorted(merged) or len(set(merged)) != len(merged):
    problems.append(f"case lists differ: unsharded {len(unsharded)}, merged {len(merged)} ({len(set(merged))} distinct)")
if diff.get("common_cases") != len(unsharded):
    problems.append(f"diff-reports compared {diff.get('common_cases')} cases of {len(unsharded)}")
if not unsharded:
    problems.append("the patterns selected no case")

timings = len(diff.get("timings") or [])
if problems:
    print(f"slurm-shards: FAIL: {shards} merged shards differ from the unsharded run:")
    for p in problems:
        print(f"  {p}")
    sys.exit(1)
print(f"slurm-shards: PASS: {shards} shards merged equal the unsharded run: {len(unsharded)} cases, "
      f"no regression, fix, outcome change, added, removed or moved value ({timings} timings differ, allowed)")
EOF
verdict=$?
set -e
say "work folder left in $work (diff in diff.json, logs in logs/)"
exit "$verdict"
