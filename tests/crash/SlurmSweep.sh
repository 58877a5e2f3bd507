#!/bin/bash
# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# A sweep emitted for Slurm (crumple-crash --emit-slurm) gives sweep.csv and sweep.png byte for byte as the
# local --sweep of the same scenario and spec.
#   SlurmSweep.sh CRUMPLE_CRASH SCENARIO SCRATCH scripts   runs the emitted batch scripts with bash, as
#                                                          Slurm's array tasks would (no cluster needed)
#   SlurmSweep.sh CRUMPLE_CRASH SCENARIO SCRATCH cluster   starts a single-node Slurm (munged, slurmctld,
#                                                          slurmd from Debian's packages) in SCRATCH and
#                                                          submits submit.sh to it; exits 77 (CTest's skip)
#                                                          saying why when it cannot start one
set -u
crash=$1 scenario=$2 scratch=$3 mode=$4
spec="speeds_km_h=20,30,40;angles_deg=0"
rm -rf "$scratch" && mkdir -p "$scratch" || exit 1
cd "$scratch" || exit 1
skip() { echo "SKIP: $*"; exit 77; }
fail() { echo "FAIL: $*"; exit 1; }

"$crash" "$scenario" --sweep "$spec" --workers 2 --out "$scratch/local" > local.log
"$crash" "$scenario" --sweep "$spec" --emit-slurm "$scratch/job" --cases-per-task 2 --slurm-time 10 ||
    fail "--emit-slurm failed"
grep -q -- "--array=0-1" job/sweep_array.sbatch || fail "3 cases at 2 per task should be an array of 2 tasks"

if [ "$mode" = scripts ]; then
    for task in 0 1; do SLURM_ARRAY_TASK_ID=$task bash job/sweep_array.sbatch || fail "task $task failed"; done
    bash job/sweep_merge.sbatch > merge.log
else
    for tool in munged slurmctld slurmd sbatch squeue sinfo scontrol; do
        command -v "$tool" > /dev/null || skip "$tool not found (apt-get install slurmctld slurmd slurm-client munge)"
    done
    [ "$(id -u)" = 0 ] || skip "a single-node Slurm needs root here (slurmd runs jobs as their users)"
    node=$(hostname -s)
    port=$((20000 + ($$ % 10000) * 2))
    export SLURM_CONF=$scratch/slurm.conf
    cleanup() {
        scontrol shutdown > /dev/null 2>&1
        sleep 1
        for pid in slurmctld.pid slurmd.pid munged.pid; do [ -f "$pid" ] && kill "$(cat "$pid")" 2> /dev/null; done
    }
    trap cleanup EXIT
    mkdir -p state spool
    head -c 1024 /dev/urandom > munge.key && chmod 400 munge.key
    munged --key-file="$scratch/munge.key" --socket="$scratch/munge.sock" --pid-file="$scratch/munged.pid" \
        --log-file="$scratch/munged.log" --seed-file="$scratch/munged.seed" || skip "munged did not start: $(tail -1 munged.log)"
    cat > slurm.conf << CONF
ClusterName=crumpletest
SlurmctldHost=$node
AuthType=auth/munge
AuthInfo=socket=$scratch/munge.sock
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$port
SlurmdPort=$((port + 1))
StateSaveLocation=$scratch/state
SlurmdSpoolDir=$scratch/spool
SlurmctldPidFile=$scratch/slurmctld.pid
SlurmdPidFile=$scratch/slurmd.pid
SlurmctldLogFile=$scratch/slurmctld.log
SlurmdLogFile=$scratch/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
NodeName=$node CPUs=$(nproc) State=UNKNOWN
PartitionName=crumple Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
    slurmctld -f "$SLURM_CONF" || skip "slurmctld did not start: $(tail -2 slurmctld.log 2> /dev/null)"
    slurmd -f "$SLURM_CONF" || skip "slurmd did not start: $(tail -2 slurmd.log 2> /dev/null)"
    for _ in $(seq 60); do
        [ "$(sinfo -h -o %t 2> /dev/null)" = idle ] && break
        sleep 1
    done
    [ "$(sinfo -h -o %t 2> /dev/null)" = idle ] || skip "the Slurm node did not come up: $(tail -2 slurmd.log 2> /dev/null)"
    ids=$(sh job/submit.sh) || fail "submit.sh failed"
    echo "submitted array and merge jobs: $ids"
    for _ in $(seq 300); do
        [ -z "$(squeue -h 2> /dev/null)" ] && [ -f job/sweep.csv ] && break
        sleep 1
    done
    [ -f job/sweep.csv ] || fail "the merge job wrote no sweep.csv in 300 s: $(squeue 2>&1; cat job/logs/* 2>&1 | tail -5)"
    cp job/logs/merge.out merge.log
fi

cat merge.log
cmp local/sweep.csv job/sweep.csv || fail "sweep.csv differs from the local sweep's"
cmp local/sweep.png job/sweep.png || fail "sweep.png differs from the local sweep's"
# The merge's verdict is the local sweep's.
[ "$(tail -1 local.log | cut -d';' -f1)" = "$(grep "cases failed" merge.log | cut -d';' -f1)" ] ||
    fail "the merge's verdict differs: $(tail -1 local.log) / $(grep "cases failed" merge.log)"
echo "PASS: the Slurm sweep ($mode) wrote sweep.csv and sweep.png byte for byte as the local sweep"
