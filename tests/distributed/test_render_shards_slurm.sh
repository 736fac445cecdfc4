#!/usr/bin/env bash
# scripts/render-shards-slurm.sbatch on a real Slurm of the test's own (one
# machine: munged, slurmctld, slurmd; slurm_cluster.sh): a 200-shot scene
# over a 4-task job array gives every picture, byte-identical to one
# process's; an array task cancelled mid-run (scancel JOB_2) leaves its
# shard short, and the array submitted again with --skip-existing completes
# the set without rendering again the pictures that were there.
#   test_render_shards_slurm.sh SHADELAB SOURCE_DIR MESH
# Exits 77 (skipped) when Slurm or munge is not installed.
set -euo pipefail
export SHADELAB=$1
source_dir=$2
mesh=$3
here=$(dirname "$0")
for program in munged slurmctld slurmd sbatch squeue scancel; do
  command -v "$program" >/dev/null || {
    echo "SKIP: $program is missing (scripts/setup installs slurmctld slurmd slurm-client munge)"
    exit 77
  }
done
source "$here/slurm_cluster.sh"
source "$here/shards_common.sh"

work=$(mktemp -d)
chmod 755 "$work" # slurmd and the jobs run as this user, but walk here too
cleanup() {
  if (($1 != 0)); then
    echo "--- the logs" >&2
    tail -n 20 "$work"/slurm/log/*.log "$work"/run/*.log >&2 2>/dev/null || true
  fi
  slurm_cluster_stop "$work/slurm"
  rm -rf "$work"
}
trap 'cleanup $?' EXIT

slurm_cluster_start "$work/slurm" || fail "the test's Slurm did not start"
write_scene "$work" "$mesh"
render_reference "$work"

sbatch_script=$source_dir/scripts/render-shards-slurm.sbatch
# submit ARRAY [render options]: the job array's id. One CPU a task, so
# that two run at once on two cores.
submit() {
  local array=$1
  shift
  (cd "$work/run" && sbatch --parsable --array="$array" --cpus-per-task=1 "$sbatch_script" \
    "../the scene.json" "$@")
}
# Waits until none of job $1's tasks is queued or running.
job_done() {
  local queued
  queued=$(squeue -h -j "$1") && [[ -z $queued ]]
}
wait_job() {
  wait_for 120 job_done "$1" || fail "job $1 did not finish"
}
# Whether shard I of N has written a picture in RUN_DIR.
shard_started() {
  local f
  for f in $(shard_files "$2" "$3"); do
    [[ -f $1/$f ]] && return 0
  done
  return 1
}

mkdir "$work/run"
job=$(submit 0-$((shards - 1)))
wait_job "$job"
check_complete "$work/run" "$work/reference"
for ((i = 0; i < shards; i++)); do
  [[ -f $work/run/shadelab-shard-${job}_$i.log ]] || fail "no log of task $i"
done

# Task 2 cancelled once its first picture is there: SIGTERM, and shadelab
# stops between shots. A shard of 50 small shots of the bunny lasts about a second
# on a quiet machine, about as long as a cancel takes to reach it, so an
# attempt in which the task finished first says nothing about the scripts
# and is tried again.
cancel_task_2() {
  local job f written=0
  rm -rf "$work/run/out"
  job=$(submit 0-$((shards - 1)))
  wait_for 60 shard_started "$work/run" 2 $shards || fail "task 2 wrote nothing"
  scancel "${job}_2"
  wait_job "$job"
  grep -q CANCELLED "$work/run/shadelab-shard-${job}_2.log" || return 1
  for f in $(shard_files 2 $shards); do
    if [[ -f $work/run/$f ]]; then
      written=$((written + 1))
    fi
  done
  ((written < shots / shards))
}
for attempt in 1 2 3 4; do
  cancel_task_2 && break
  ((attempt < 4)) || fail "task 2 finished before each of $attempt cancels reached it"
  echo "task 2 finished before the cancel reached it; again"
done
before=$(mtimes "$work/run")

job=$(submit 0-$((shards - 1)) --skip-existing)
wait_job "$job"
check_complete "$work/run" "$work/reference"
# The pictures that were there were not written again.
unchanged=$(comm -12 <(echo "$before") <(mtimes "$work/run") | wc -l)
((unchanged == $(wc -l <<<"$before"))) || fail "the resubmission wrote again $(($(wc -l <<<"$before") - unchanged)) pictures that existed"

# A part of the array alone must not take its part for the whole (task 2
# of a 0-2 array would be shard 2/3): refused, unless SHADELAB_SHARDS says N.
rm -f "$work/run/out/"*
job=$(submit 2)
wait_job "$job"
grep -q 'SHADELAB_SHARDS' "$work/run/shadelab-shard-${job}_2.log" || fail "a partial array was not refused"
[[ -z $(ls "$work/run/out") ]] || fail "a refused task rendered"
job=$(SHADELAB_SHARDS=$shards submit 2)
wait_job "$job"
diff <(cd "$work/run" && ls out/* | sort) <(shard_files 2 $shards | sort) >/dev/null ||
  fail "SHADELAB_SHARDS=4 with --array=2 did not render shard 2/4"
echo "OK: $shots shots over $shards Slurm array tasks, a cancelled task completed by resubmission"
