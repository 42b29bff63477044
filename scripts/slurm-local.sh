#!/usr/bin/env bash
# Brings up (or stops) a one-node SLURM cluster on localhost, without systemd, to run
# scripts/bench-slurm.sh for real (tests, CI; docs/BENCHMARKING.md, "Run on a cluster").
#
#   scripts/slurm-local.sh start    # installs munge + SLURM when missing, starts munged, slurmctld, slurmd
#   scripts/slurm-local.sh status   # sinfo and squeue; exit 0 when the cluster answers, 3 when it is down
#   scripts/slurm-local.sh stop     # cancels its jobs, stops the daemons it started, removes its directory
#   scripts/slurm-local.sh env      # prints the export line below
#
# Run as root (or with sudo). The cluster's slurm.conf, state, spool and logs live in a fresh
# temporary directory (mktemp -d) that $FOLDKIT_SLURM_DIR (default /tmp/foldkit-slurm) links to,
# so `stop` finds it and the configuration has a fixed path. SLURM's tools read
# /etc/slurm/slurm.conf unless SLURM_CONF says otherwise: `start` prints the line to use,
#   export SLURM_CONF=/tmp/foldkit-slurm/slurm.conf
# or use `eval "$(scripts/slurm-local.sh env)"`. The node is `localhost` (all CPUs, ~90 % of the
# memory), in partition `debug`; slurmctld and slurmd listen on SLURM's default ports 6817/6818,
# so do not start it beside another slurmctld on the same machine.
set -euo pipefail

usage() { sed -n '2,17p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }

link=${FOLDKIT_SLURM_DIR:-/tmp/foldkit-slurm}
conf=$link/slurm.conf
packages=(munge slurmctld slurmd slurm-client)

log() { echo "slurm-local: $*" >&2; }
die() { log "$*"; exit 1; }

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"
  elif command -v sudo >/dev/null; then sudo "$@"
  else die "needs root (or sudo) for: $*"
  fi
}

install_packages() {
  local missing=() p
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  log "installing ${missing[*]}"
  as_root env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
}

# The PID in a pidfile, when that process is alive and is the named program.
live_pid() {
  local file=$1 name=$2 pid
  [ -r "$file" ] || return 1
  pid=$(tr -dc 0-9 <"$file")
  [ -n "$pid" ] && [ -r "/proc/$pid/comm" ] || return 1
  case "$(cat "/proc/$pid/comm")" in "$name"*) echo "$pid" ;; *) return 1 ;; esac
}

munge_ok() { munge -n 2>/dev/null | unmunge >/dev/null 2>&1; }

start_munge() {
  local dir=$1
  if munge_ok; then
    log "munged already running"
    return 0
  fi
  [ -s /etc/munge/munge.key ] || as_root runuser -u munge -- mungekey --create --keyfile=/etc/munge/munge.key
  # systemd makes munge's runtime directory; without it, munged cannot create its socket.
  as_root install -d -o munge -g munge -m 0755 /run/munge
  as_root runuser -u munge -- /usr/sbin/munged
  for _ in $(seq 50); do
    munge_ok && break
    sleep 0.1
  done
  munge_ok || die "munged does not answer (munge -n | unmunge); see /var/log/munge/munged.log"
  touch "$dir/munged.started"  # stop ends munged only when this script started it
}

write_conf() {
  local dir=$1 cpus mem_kb
  cpus=$(nproc)
  mem_kb=$(awk '/^MemTotal:/ {print $2}' /proc/meminfo)
  # Configured memory above the node's makes the node invalid; a job asking for more than
  # RealMemory (sbatch --mem) is refused at submission.
  cat >"$dir/slurm.conf" <<EOF
# One-node cluster on localhost, written by scripts/slurm-local.sh
ClusterName=foldkit-local
SlurmctldHost=localhost
SlurmUser=root
AuthType=auth/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
JobCompType=jobcomp/filetxt
JobCompLoc=$dir/jobcomp.txt
MailProg=/bin/true
ReturnToService=2
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$((mem_kb * 9 / 10 / 1024)) State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
}

show_logs() {
  local f
  for f in "$link"/slurmctld.log "$link"/slurmd.log; do
    [ -r "$f" ] && { log "--- last lines of $f"; tail -n 20 "$f" >&2; }
  done
  return 0
}

running() { [ -e "$link/slurm.conf" ] && live_pid "$link/slurmctld.pid" slurmctld >/dev/null; }

cmd_start() {
  local dir state=""
  if running; then
    log "already running ($link -> $(readlink -f "$link"))"
    echo "export SLURM_CONF=$conf"
    return 0
  fi
  if [ -e "$link" ] || [ -L "$link" ]; then
    log "removing the leftovers of an earlier cluster at $link"
    cmd_stop 2>/dev/null || true
  fi
  install_packages
  dir=$(mktemp -d "${link}.XXXXXX")
  chmod 755 "$dir"
  mkdir -p "$dir/state" "$dir/spool"
  ln -sfn "$dir" "$link"
  write_conf "$dir"
  export SLURM_CONF=$conf
  start_munge "$dir"
  as_root slurmctld -f "$conf"
  as_root slurmd -f "$conf" -N localhost
  # Bounded wait for the node to register; about 2 s.
  for _ in $(seq 60); do
    state=$(sinfo -h -n localhost -o %T 2>/dev/null || true)
    [ "$state" = idle ] && break
    sleep 0.5
  done
  if [ "$state" != idle ]; then
    show_logs
    die "node localhost is '${state:-not answering}' after 30 s, not idle; stop with: $0 stop"
  fi
  log "cluster up: node localhost idle in partition debug ($link -> $dir)"
  echo "export SLURM_CONF=$conf"
}

# stop_pids FILE NAME [FILE NAME ...]: SIGTERM to each live one at once, SIGKILL after 10 s.
stop_pids() {
  local pids=() names=() pid i
  while [ $# -ge 2 ]; do
    if pid=$(live_pid "$1" "$2"); then
      as_root kill "$pid" 2>/dev/null || true
      pids+=("$pid") names+=("$2")
    fi
    shift 2
  done
  for i in "${!pids[@]}"; do
    for _ in $(seq 100); do
      [ -e "/proc/${pids[$i]}" ] || break
      sleep 0.1
    done
    if [ -e "/proc/${pids[$i]}" ]; then
      as_root kill -9 "${pids[$i]}" 2>/dev/null || true
      log "killed ${names[$i]} (${pids[$i]})"
    else
      log "stopped ${names[$i]} (${pids[$i]})"
    fi
  done
}

cmd_stop() {
  local dir jobs
  if [ ! -e "$link" ] && [ ! -L "$link" ]; then
    log "not running (no $link)"
    return 0
  fi
  dir=$(readlink -f "$link")
  export SLURM_CONF=$conf
  if running; then
    jobs=$(squeue -h -o %A 2>/dev/null | sort -u | tr '\n' ' ' || true)
    if [ -n "${jobs// /}" ]; then
      log "cancelling jobs $jobs"
      # shellcheck disable=SC2086 # one job ID per word
      scancel $jobs 2>/dev/null || true
      sleep 1
    fi
  fi
  # munged only when this script started it.
  if [ -e "$dir/munged.started" ]; then
    stop_pids "$dir/slurmd.pid" slurmd "$dir/slurmctld.pid" slurmctld /run/munge/munged.pid munged
  else
    stop_pids "$dir/slurmd.pid" slurmd "$dir/slurmctld.pid" slurmctld
  fi
  # Only remove what this script made: a link to a directory named like its own.
  case "$dir" in "$link".??????) rm -rf "$dir" ;; esac
  rm -f "$link"
  log "stopped; removed $dir"
}

cmd_status() {
  if ! running; then
    log "not running"
    return 3
  fi
  export SLURM_CONF=$conf
  echo "export SLURM_CONF=$conf"
  sinfo
  squeue
}

[ $# -eq 1 ] || usage
case "$1" in
  start) cmd_start ;;
  stop) cmd_stop ;;
  status) cmd_status ;;
  env) echo "export SLURM_CONF=$conf" ;;
  -h|--help) usage ;;
  *) usage ;;
esac
