#!/usr/bin/env bash
# Starts a single-node Slurm cluster on this machine, for testing groundtruth's job arrays
# (scripts/slurm-shards.sh). Debian 12, as root; safe to run again. No systemd needed: the daemons
# are started directly, so it also works in a container.
#
#   bash scripts/slurm-cluster.sh          # install slurm-wlm and munge if missing, start, wait for the node
#   bash scripts/slurm-cluster.sh stop     # stop the daemons this script started
#   bash scripts/slurm-cluster.sh status   # what runs, what sinfo says
#
# What it does:
#   - installs slurm-wlm and munge (apt-get, noninteractive) when they are missing;
#   - creates /etc/munge/munge.key when there is none, starts munged as the munge user;
#   - writes /etc/slurm/slurm.conf for this host only when that file is absent or was written by
#     this script (its first line is the marker below): an administrator's configuration is never
#     overwritten. The node is this host (`hostname -s`) with the CPUs and RealMemory `slurmd -C`
#     measures, reached over 127.0.0.1; one partition `groundtruth`; select/cons_tres on cores;
#     proctrack/linuxproc and task/none (no cgroups, which containers often lack); no accounting.
#     The controller runs as the `slurm` user the Debian package creates (root if it is missing,
#     which is acceptable for a throw-away single-node test cluster, never for a shared one);
#     jobs run as whoever submits them (root here). State in /var/spool/slurmctld and
#     /var/spool/slurmd, logs in /var/log/slurm/;
#   - starts slurmctld and slurmd as daemons and waits until `sinfo` shows the node idle.
#
# With a slurm.conf this script did not write it starts nothing: it uses the cluster when its
# controller answers and stops with an error otherwise.
#
# Environment: GT_SLURM_TIMEOUT (seconds for each wait, default 120).
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive

conf=/etc/slurm/slurm.conf
marker='# groundtruth single-node test cluster: written by scripts/slurm-cluster.sh, which rewrites this file while this line stays first'
state_dir=/run/groundtruth-slurm # which daemons this script started (gone after a reboot, as they are)
timeout=${GT_SLURM_TIMEOUT:-120}
partition=groundtruth
munge_pidfile=/run/munge/munged.pid
slurmctld_pidfile=/run/slurmctld.pid
slurmd_pidfile=/run/slurmd.pid

say() { echo "slurm-cluster: $*"; }
die() {
  echo "slurm-cluster: error: $*" >&2
  exit 1
}

case "$timeout" in '' | *[!0-9]*) die "GT_SLURM_TIMEOUT must be a whole number of seconds, not '$timeout'" ;; esac

# alive PID: the process exists and is not a zombie (a daemon killed in a container may stay a
# zombie for a while when PID 1 is slow to reap it).
alive() {
  local stat
  stat=$(sed 's/^.*) //' "/proc/$1/stat" 2>/dev/null) || return 1
  case "${stat%% *}" in '' | Z | X) return 1 ;; esac
}

# pid_of NAME PIDFILE: prints the pid when the pidfile names a live process called NAME.
pid_of() {
  local pid comm
  [ -r "$2" ] || return 1
  pid=$(tr -dc '0-9' <"$2")
  [ -n "$pid" ] && alive "$pid" || return 1
  comm=$(cat "/proc/$pid/comm" 2>/dev/null) || return 1
  case "$comm" in "$1"*) echo "$pid" ;; *) return 1 ;; esac
}

started_by_us() { [ -f "$state_dir/$1" ]; }

# stop_daemon NAME PIDFILE: stops NAME when this script started it.
stop_daemon() {
  local name=$1 pidfile=$2 pid waited=0
  if ! started_by_us "$name"; then
    if pid=$(pid_of "$name" "$pidfile"); then say "$name (pid $pid) was not started by this script; left running"; fi
    return 0
  fi
  if ! pid=$(pid_of "$name" "$pidfile"); then
    say "$name is not running"
    rm -f "$state_dir/$name"
    return 0
  fi
  kill -TERM "$pid"
  while alive "$pid"; do
    if [ "$waited" -ge "$timeout" ]; then
      say "$name (pid $pid) ignored SIGTERM for ${timeout}s; sending SIGKILL"
      kill -KILL "$pid" 2>/dev/null || true
      sleep 1
      break
    fi
    sleep 1
    waited=$((waited + 1))
  done
  rm -f "$state_dir/$name"
  say "stopped $name (pid $pid)"
}

stop_all() {
  stop_daemon slurmd "$slurmd_pidfile"
  stop_daemon slurmctld "$slurmctld_pidfile"
  stop_daemon munged "$munge_pidfile"
}

ours() { [ -f "$conf" ] && [ "$(head -n 1 "$conf")" = "$marker" ]; }

node_name() { hostname -s; }

node_state() { sinfo -h -N -n "$(node_name)" -o '%T' 2>/dev/null | head -n 1; }

show_logs() {
  local log
  for log in /var/log/slurm/slurmctld.log /var/log/slurm/slurmd.log; do
    if [ -f "$log" ]; then
      echo "--- last lines of $log" >&2
      tail -n 15 "$log" >&2
    fi
  done
}

if [ "${1:-}" = stop ]; then
  stop_all
  exit 0
fi
if [ "${1:-}" = status ]; then
  for d in munged:$munge_pidfile slurmctld:$slurmctld_pidfile slurmd:$slurmd_pidfile; do
    name=${d%%:*}
    if pid=$(pid_of "$name" "${d#*:}"); then
      if started_by_us "$name"; then by=" (started by this script)"; else by=""; fi
      say "$name running, pid $pid$by"
    else
      say "$name not running"
    fi
  done
  if command -v sinfo >/dev/null 2>&1; then sinfo || true; fi
  exit 0
fi
[ $# -eq 0 ] || die "unknown argument '$1' (use no argument to start, 'stop' or 'status')"
[ "$(id -u)" -eq 0 ] || die "run as root (it installs packages and starts daemons)"

# --- packages
missing=()
for p in slurm-wlm munge; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  say "installing ${missing[*]}"
  apt-get update -q
  # Debian's maintainer scripts try to start the daemons through invoke-rc.d; where no init
  # system runs (a container) that is refused and harmless: this script starts them below.
  apt-get install -y -q "${missing[@]}"
fi

# --- the configuration
if [ -f "$conf" ] && ! ours; then
  say "$conf was not written by this script: it is left alone and no daemon is started"
  if scontrol ping 2>/dev/null | grep -q 'is UP'; then
    say "the configured controller answers; using that cluster:"
    sinfo
    exit 0
  fi
  die "the cluster configured in $conf does not answer (scontrol ping). Start it as its administrator does, or move that file away to let this script write a single-node test configuration"
fi

host=$(node_name)
[ -n "$host" ] || die "hostname -s printed nothing"
# slurmd -C prints this machine's node line (NodeName=... CPUs=... RealMemory=...) and an UpTime line.
node_line=$(slurmd -C | grep '^NodeName=' | head -n 1) || die "slurmd -C did not describe this machine"
case "$node_line" in "NodeName=$host "*) ;; *) die "slurmd -C names another node than '$host': $node_line" ;; esac
if id slurm >/dev/null 2>&1; then slurm_user=slurm; else slurm_user=root; fi

desired=$(
  cat <<EOF
$marker
# Delete that line to keep your own edits: the script then never touches this file again.
# One node, this machine ($host), reached over the loopback; for tests, not for a shared cluster.
ClusterName=groundtruth
SlurmctldHost=$host(127.0.0.1)
SlurmUser=$slurm_user
SlurmdUser=root
AuthType=auth/munge
StateSaveLocation=/var/spool/slurmctld
SlurmdSpoolDir=/var/spool/slurmd
SlurmctldPidFile=$slurmctld_pidfile
SlurmdPidFile=$slurmd_pidfile
SlurmctldLogFile=/var/log/slurm/slurmctld.log
SlurmdLogFile=/var/log/slurm/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
# no cgroups: containers often have none to delegate
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
JobAcctGatherType=jobacct_gather/none
MpiDefault=none
SwitchType=switch/none
ReturnToService=2
# finished jobs stay visible to scontrol for 10 minutes (their exit codes)
MinJobAge=600
$node_line NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=$partition Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
)

changed=no
if [ ! -f "$conf" ] || [ "$(cat "$conf")" != "$desired" ]; then
  mkdir -p "$(dirname "$conf")"
  printf '%s\n' "$desired" >"$conf.tmp-$$"
  chmod 0644 "$conf.tmp-$$"
  mv "$conf.tmp-$$" "$conf"
  say "wrote $conf (node $host: ${node_line#NodeName="$host" })"
  changed=yes
fi

mkdir -p "$state_dir" /var/spool/slurmctld /var/spool/slurmd /var/log/slurm
chown "$slurm_user": /var/spool/slurmctld /var/log/slurm
chmod 0755 /var/spool/slurmctld /var/spool/slurmd

# A changed configuration restarts the Slurm daemons this script started (never others).
if [ "$changed" = yes ]; then
  for d in slurmd:$slurmd_pidfile slurmctld:$slurmctld_pidfile; do
    if started_by_us "${d%%:*}" && pid_of "${d%%:*}" "${d#*:}" >/dev/null; then
      say "configuration changed: restarting ${d%%:*}"
      stop_daemon "${d%%:*}" "${d#*:}"
    fi
  done
fi

# wait_for SECONDS DAEMON PIDFILE DESCRIPTION COMMAND...: runs COMMAND once a second until it
# succeeds; stops early when DAEMON has exited.
wait_for() {
  local limit=$1 daemon=$2 pidfile=$3 what=$4 waited=0
  shift 4
  until "$@" >/dev/null 2>&1; do
    if [ "$waited" -ge "$limit" ]; then
      show_logs
      die "$what: not ready after ${limit}s"
    fi
    if [ "$waited" -ge 3 ] && ! pid_of "$daemon" "$pidfile" >/dev/null; then
      show_logs
      die "$daemon exited while starting ($what failed)"
    fi
    sleep 1
    waited=$((waited + 1))
  done
}

# --- munge
key=/etc/munge/munge.key
if [ ! -s "$key" ]; then
  say "creating $key"
  install -d -o munge -g munge -m 0700 /etc/munge
  mungekey --create --keyfile="$key"
  chown munge:munge "$key"
  chmod 0600 "$key"
fi
if pid=$(pid_of munged "$munge_pidfile"); then
  say "munged already running (pid $pid)"
else
  install -d -o munge -g munge -m 0755 /run/munge
  runuser -u munge -- /usr/sbin/munged --pid-file="$munge_pidfile" ||
    die "munged did not start (see /var/log/munge/munged.log)"
  touch "$state_dir/munged"
  say "started munged"
fi
munge_works() { munge -n | unmunge; }
wait_for "$timeout" munged "$munge_pidfile" "munge -n | unmunge" munge_works

# --- slurmctld, then slurmd
# start_slurm_daemon NAME PIDFILE: starts the daemon unless it runs, and records that we started it.
start_slurm_daemon() {
  local name=$1 pidfile=$2 pid
  if pid=$(pid_of "$name" "$pidfile"); then
    say "$name already running (pid $pid)"
    return
  fi
  "$name" || {
    show_logs
    die "$name did not start"
  }
  touch "$state_dir/$name"
  say "started $name"
}
start_slurm_daemon slurmctld "$slurmctld_pidfile"
controller_up() { scontrol ping | grep -q 'is UP'; }
wait_for "$timeout" slurmctld "$slurmctld_pidfile" "scontrol ping" controller_up
start_slurm_daemon slurmd "$slurmd_pidfile"

# --- the node
waited=0
resumed=no
while :; do
  state=$(node_state || true)
  case "$state" in
    idle) break ;;
    down* | drain* | fail*)
      # ReturnToService=2 brings back a node that registers after an unclean stop; a node left
      # drained (by hand, or before that setting) is resumed once, as this is our test cluster.
      if [ "$resumed" = no ] && [ "$waited" -ge 5 ]; then
        say "node $host is $state ($(sinfo -h -N -n "$host" -o '%E')): resuming it"
        scontrol update nodename="$host" state=resume || true
        resumed=yes
      fi
      ;;
  esac
  if [ "$waited" -ge "$timeout" ]; then
    show_logs
    die "node $host is not idle after ${timeout}s: sinfo says '${state:-nothing}' (reason: $(sinfo -h -N -n "$host" -o '%E' 2>/dev/null || true))"
  fi
  sleep 1
  waited=$((waited + 1))
done
say "node $host is idle in partition $partition (stop with: bash scripts/slurm-cluster.sh stop)"
sinfo
