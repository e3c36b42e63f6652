#!/usr/bin/env bash
# Runs a command against a private one-node Slurm cluster started on this machine, then stops
# everything it started. Made for CI (root, fresh Debian bookworm, no systemd) to test job arrays.
#   tools/slurm-local.sh run -- COMMAND [ARGS...]
# COMMAND runs with SLURM_CONF exported, so `sbatch --wait --array=0-3 job.sh` inside it talks to
# the private cluster; the script exits with COMMAND's status.
# SLURM_LOCAL_KEEP=1 keeps the temporary directory (config, state, logs) and prints where it is.
set -euo pipefail

me="slurm-local"
say() { echo "$me: $*" >&2; }
die() { echo "$me: error: $*" >&2; exit 1; }
usage() {
  cat >&2 <<'EOF'
usage: tools/slurm-local.sh run -- COMMAND [ARGS...]
  Starts munged (if none is running), slurmctld and slurmd on a private config in a temporary
  directory, runs COMMAND with SLURM_CONF exported, stops what it started and returns COMMAND's
  exit status. SLURM_LOCAL_KEEP=1 keeps the temporary directory with the logs.
EOF
  exit 2
}

case "${1:-}" in
  run) shift ;;
  *) usage ;;
esac
[ "${1:-}" = "--" ] && shift
(($#)) || usage

if [ "$(id -u)" -ne 0 ]; then
  echo "$me: needs root to start munged, slurmctld and slurmd" >&2
  exit 1
fi

# Daemons and mungekey live in sbin, which a CI environment's PATH may lack.
export PATH="$PATH:/usr/sbin:/sbin"

# --- What this run started; the EXIT trap stops exactly these and nothing else. ---
tmp=""
munged_pid=""
slurmctld_pid=""
slurmd_pid=""
our_policy_rc=""

# True while PID runs; a zombie (exited, not yet reaped) counts as gone.
alive() {
  local state
  [ -r "/proc/$1/stat" ] || return 1
  state="$(sed 's/^.*) //' "/proc/$1/stat" 2>/dev/null | cut -c1)" || return 1
  [ -n "$state" ] && [ "$state" != "Z" ]
}

# Sends SIGTERM, waits up to 30 s for the exit, then SIGKILL. All daemons are our children, so
# `wait` reaps them and nothing is left behind as a zombie either.
# shellcheck disable=SC2317 # only called from the EXIT trap, which shellcheck does not follow
stop_pid() {
  local pid="$1" name="$2" i
  [ -n "$pid" ] || return 0
  if alive "$pid"; then
    kill -TERM "$pid" 2>/dev/null || true
    for ((i = 0; i < 150; i++)); do
      alive "$pid" || break
      sleep 0.2
    done
    if alive "$pid"; then
      say "$name (pid $pid) ignored SIGTERM for 30 s; killing it"
      kill -KILL "$pid" 2>/dev/null || true
    fi
  fi
  wait "$pid" 2>/dev/null || true
}

# shellcheck disable=SC2317 # the EXIT trap
cleanup() {
  local rc=$?
  trap - EXIT INT TERM
  set +e
  [ -n "$our_policy_rc" ] && rm -f "$our_policy_rc"
  # Jobs still queued or running (COMMAND failed or was interrupted) would leave slurmstepd and
  # job processes behind once slurmd is gone: cancel them while the daemons still run. The
  # cluster is private, so every job in it is ours.
  if [ -n "$slurmctld_pid" ] && alive "$slurmctld_pid"; then
    local jobs i
    jobs="$(timeout 10 squeue -h -o %A 2>/dev/null)"
    if [ -n "$jobs" ]; then
      # shellcheck disable=SC2086 # one job id per word
      timeout 10 scancel $jobs 2>/dev/null
      for ((i = 0; i < 50; i++)); do
        # squeue's default states are the unfinished ones (pending, running, completing).
        [ -z "$(timeout 5 squeue -h -o %A 2>/dev/null)" ] && break
        sleep 0.2
      done
    fi
  fi
  # slurmd first, so that slurmctld does not see its node go away mid-job.
  stop_pid "$slurmd_pid" slurmd
  stop_pid "$slurmctld_pid" slurmctld
  stop_pid "$munged_pid" munged
  if [ -n "$tmp" ] && [ -d "$tmp" ]; then
    if [ "${SLURM_LOCAL_KEEP:-0}" = 1 ]; then
      say "kept $tmp (logs: $tmp/log)"
    else
      rm -rf "$tmp"
    fi
  fi
  exit "$rc"
}
trap cleanup EXIT
# Ctrl-C / kill: exit with the usual status, which runs the EXIT trap above.
trap 'exit 130' INT
trap 'exit 143' TERM

tmp="$(mktemp -d /tmp/slurm-local.XXXXXX)"
mkdir -p "$tmp/log" "$tmp/state" "$tmp/spool" "$tmp/run"

# Prints the last lines of each given log.
tails() {
  local f
  for f in "$@"; do
    [ -s "$f" ] || continue
    echo "---- last lines of $f" >&2
    tail -n 12 "$f" >&2
  done
}

# After the logs' tails, prints the reason a daemon gave up: its last "fatal" line, else its
# last "error" line (Slurm also logs harmless errors at start-up, e.g. the missing PMIx library
# or the fresh state files).
explain() {
  local line="" f pattern
  tails "$@"
  for pattern in 'fatal' 'error'; do
    for f in "$@"; do
      [ -s "$f" ] || continue
      line="$(grep -hi "$pattern" "$f" | tail -n 1)" || true
      [ -n "$line" ] && break 2
    done
  done
  [ -n "$line" ] && echo "$me: reason: $line" >&2
  return 0
}

# --- 1. Packages. ---
# --no-install-recommends: slurm-wlm recommends ~27 plugin/-dev packages (hdf5, influxdb, mysql...)
# that a one-node test does not use; the basic plugins come as a dependency.
missing=()
for p in slurm-wlm munge; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  say "installing ${missing[*]}"
  # The packages' postinst scripts start munge, slurmctld and slurmd system services. Those
  # would be left running (and slurmctld/slurmd have no config yet): forbid service starts for
  # the install, as Debian's Docker images do permanently, unless a policy already exists.
  if [ ! -e /usr/sbin/policy-rc.d ]; then
    our_policy_rc=/usr/sbin/policy-rc.d
    printf '#!/bin/sh\n# temporary, from slurm-local.sh\nexit 101\n' >"$our_policy_rc"
    chmod 755 "$our_policy_rc"
  fi
  if ! { apt-get update -qq &&
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
      "${missing[@]}"; } >"$tmp/log/apt.log" 2>&1; then
    tail -n 20 "$tmp/log/apt.log" >&2
    die "apt-get could not install ${missing[*]} (see above)"
  fi
  if [ -n "$our_policy_rc" ]; then
    rm -f "$our_policy_rc"
    our_policy_rc=""
  fi
fi

# --- 2. munged. ---
# A running munged (the machine's own, or another run's) is used as it is and left alone.
if munge -n 2>/dev/null | unmunge >/dev/null 2>&1; then
  say "using the munged already running"
else
  # The key: Debian's postinst makes it, but a machine may lack it (deleted, or an image that
  # skipped postinst). munged refuses a key that is not owned by its user or readable by others.
  if [ ! -s /etc/munge/munge.key ]; then
    say "creating /etc/munge/munge.key"
    install -d -o munge -g munge -m 0700 /etc/munge
    runuser -u munge -- mungekey --create --keyfile=/etc/munge/munge.key ||
      die "mungekey could not create /etc/munge/munge.key"
  fi
  chown munge:munge /etc/munge/munge.key
  chmod 0400 /etc/munge/munge.key
  # /run is a tmpfs: its munge directory (socket, pid file) may not exist yet. Debian's init
  # script creates it the same way.
  install -d -o munge -g munge -m 0755 /run/munge
  # As Debian runs it: as the munge user. --foreground, so that the PID is our child's and
  # `wait` works; setsid and setpriv exec (no wrapper process), see the daemons below for
  # setsid. munged logs to stderr in the foreground.
  setsid setpriv --reuid=munge --regid=munge --init-groups \
    munged --foreground >"$tmp/log/munged.log" 2>&1 &
  munged_pid=$!
  for ((i = 0; i < 50; i++)); do
    munge -n 2>/dev/null | unmunge >/dev/null 2>&1 && break
    alive "$munged_pid" || break
    sleep 0.2
  done
  if ! munge -n 2>/dev/null | unmunge >/dev/null 2>&1; then
    explain "$tmp/log/munged.log" /var/log/munge/munged.log
    die "munged did not start (see reason above)"
  fi
  say "started munged (pid $munged_pid, as user munge)"
fi

# --- 3. Private configuration. ---
# Ports: the first free ones from 16817 up, so as not to collide with a Slurm already running
# (6817/6818) nor with another run of this script.
port_free() { ! (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null; }
next_free_port() {
  local p="$1"
  while ! port_free "$p"; do
    p=$((p + 1))
    ((p < 17817)) || die "no free TCP port in 16817-17816"
  done
  echo "$p"
}
ctld_port="$(next_free_port 16817)"
slurmd_port="$(next_free_port $((ctld_port + 1)))"

node="$(hostname -s)"
cpus="$(nproc)"
# RealMemory must not exceed what slurmd finds, or the node is drained: 1000 MB, or half the
# machine's memory where that is less.
mem_mb=$(($(awk '/^MemTotal:/ {print $2}' /proc/meminfo) / 1024))
real_mem=1000
((mem_mb / 2 < real_mem)) && real_mem=$((mem_mb / 2))

export SLURM_CONF="$tmp/slurm.conf"
cat >"$SLURM_CONF" <<EOF
# Written by tools/slurm-local.sh: a private one-node cluster, everything under $tmp.
ClusterName=slurmlocal
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/run/slurmctld.pid
SlurmdPidFile=$tmp/run/slurmd.pid
SlurmctldLogFile=$tmp/log/slurmctld.log
SlurmdLogFile=$tmp/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
# No cgroup handling: works in containers and without systemd.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MailProg=/bin/true
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$real_mem State=UNKNOWN
PartitionName=local Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
# Read from the directory of SLURM_CONF.
cat >"$tmp/cgroup.conf" <<'EOF'
CgroupPlugin=autodetect
IgnoreSystemd=yes
EOF

# --- 4. slurmctld and slurmd. ---
# -D (foreground) in the background: $! is the daemon itself, recorded for the EXIT trap.
# setsid (which execs, as our child is no process group leader) puts each daemon in its own
# session: a Ctrl-C in the terminal would otherwise reach them too, they would shut down at once
# and leave the running jobs' slurmstepd behind, and sbatch --wait retrying forever.
say "starting slurmctld (port $ctld_port) and slurmd (port $slurmd_port), node $node, $cpus CPUs"
setsid slurmctld -D -f "$SLURM_CONF" >"$tmp/log/slurmctld.out" 2>&1 &
slurmctld_pid=$!
setsid slurmd -D -f "$SLURM_CONF" >"$tmp/log/slurmd.out" 2>&1 &
slurmd_pid=$!

# With -D, each daemon logs everything to stderr as well, and also what it says before its
# log file is open (config errors): the .out files are the ones to show.
logs=("$tmp/log/slurmctld.out" "$tmp/log/slurmd.out")
state=""
deadline=$((SECONDS + 60))
while :; do
  # A daemon that exits now will not come back: say why at once instead of waiting 60 s.
  if ! alive "$slurmctld_pid"; then
    explain "$tmp/log/slurmctld.out"
    die "slurmctld exited during start-up (see reason above)"
  fi
  if ! alive "$slurmd_pid"; then
    explain "$tmp/log/slurmd.out"
    die "slurmd exited during start-up (see reason above)"
  fi
  state="$(timeout 10 sinfo -h -N -n "$node" -o %T 2>/dev/null | head -n 1)" || state=""
  [ "$state" = idle ] && break
  # "unknown" and "down" pass while slurmd registers; an invalid or drained node (e.g. more
  # CPUs or memory configured than slurmd finds) stays so: fail now, with slurmctld's reason.
  case "$state" in
    inval* | drain*)
      tails "${logs[@]}"
      die "node $node is $state: $(timeout 10 sinfo -h -N -n "$node" -o %E 2>/dev/null)"
      ;;
  esac
  if ((SECONDS >= deadline)); then
    explain "${logs[@]}"
    die "node $node not idle after 60 s (last state: '${state:-no answer from slurmctld}')"
  fi
  sleep 0.5
done
say "node $node idle; running: $*"

# --- 5. The command. Its status is the script's; the EXIT trap stops the daemons. ---
status=0
"$@" || status=$?
exit "$status"
