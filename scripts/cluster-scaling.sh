#!/usr/bin/env bash
# Scaling on one machine: the same job rendered by one member pinned to core 0, then by two members pinned to
# cores 0 and 1 (taskset), each run alternated ROUNDS times. Each start renders the job twice: cold (the first
# job of fresh JVMs, which also compile the render path just-in-time on the pinned cores, each member its own)
# and warm (the same job again, as a running service meets it). Prints each job's render time (its status's
# elapsedMillis), the tile counts per member and the CPU time each member's JVM used during the job (on a
# machine shared with other work the wall time says little; the CPU time says what the cluster costs). Default job: scenes/glass-pattern.json at 960x720, 36 samples.
#
#   scripts/cluster-scaling.sh [--rounds 2] [--http-port 8290] [--cluster-port 5790]
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
jar="${STUDIO_JAR:-$root/backend/server/target/studio.jar}"
java="${JAVA:-java}"
rounds=2
http=8290
cluster=5790
while [[ $# -gt 0 ]]; do
  case "$1" in
    --rounds) rounds="$2"; shift 2 ;;
    --http-port) http="$2"; shift 2 ;;
    --cluster-port) cluster="$2"; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
work="$(mktemp -d)"
# the members' shared secret (a clustered member refuses to start without one)
export STUDIO_CLUSTER_SECRET="${STUDIO_CLUSTER_SECRET:-$(openssl rand -base64 48)}"
python3 - "$root/scenes/glass-pattern.json" "$work/scene.json" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
scene["image"].update(width=960, height=720)
scene["render"]["samples"] = 36
json.dump(scene, open(sys.argv[2], "w"))
PY

pids=()
stop_all() {
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null && wait "$pid" 2>/dev/null || true; done
  pids=()
}
trap 'stop_all; rm -rf "$work"' EXIT
field() { python3 -c "import json,sys; d=json.load(sys.stdin); print(eval('d' + sys.argv[1]))" "$1"; }
until_true_every() {
  local period=$1 seconds=$2; shift 2
  local deadline=$((SECONDS + seconds))
  until "$@"; do
    [[ $SECONDS -lt $deadline ]] || { echo "timed out: $*" >&2; exit 1; }
    sleep "$period"
  done
}
until_true() {
  local seconds=$1; shift
  local deadline=$((SECONDS + seconds))
  until "$@"; do
    [[ $SECONDS -lt $deadline ]] || { echo "timed out: $*" >&2; exit 1; }
    sleep 0.2
  done
}
# the health's details go to signed-in callers only (docs/security.md); the metric is open with sign-in off
members_up() {
  [[ "$(curl -fsS "http://127.0.0.1:$http/actuator/prometheus" 2>/dev/null \
        | sed -n 's/^studio_cluster_members\({[^}]*}\)\{0,1\} \([0-9.]*\).*/\2/p' | head -1)" =~ ^$1(\.0)?$ ]]
}

# start CORE INDEX [cluster options...]
start() {
  local core=$1 i=$2; shift 2
  taskset -c "$core" "$java" -Xmx1g -jar "$jar" --server.port=$((http + i)) --studio.render-threads=1 "$@" \
    >"$root/backend/server/target/cluster-scaling-$i.log" 2>&1 &
  pids+=($!)
}

# CPU seconds (user + system) the process has used
cpu() { awk '{ printf "%.2f", ($14 + $15) / 100 }' "/proc/$1/stat"; }

run_job() {
  local id before=()
  for pid in "${pids[@]}"; do before+=("$(cpu "$pid")"); done
  id="$(curl -fsS -H 'Content-Type: application/json' --data-binary "@$work/scene.json" "http://127.0.0.1:$http/api/jobs" \
    | field "['id']")"
  # asked once a second with curl and grep alone: a Python start five times a second took some 15% of a
  # core from the pinned members (the job's time is the server's own figure, whenever it is read)
  done_() { curl -fsS "http://127.0.0.1:$http/api/jobs/$id" | grep -Eq '"state":"(done|failed|cancelled)"'; }
  until_true_every 1 1200 done_
  curl -fsS "http://127.0.0.1:$http/api/jobs/$id" | python3 -c "
import json, sys
s = json.load(sys.stdin)
print('  %s in %.1f s, tiles per member %s' % (s['state'], s['elapsedMillis'] / 1000, s.get('workers', '-')))"
  local i=0
  for pid in "${pids[@]}"; do
    echo "  member $i: $(python3 -c "print('%.1f' % ($(cpu "$pid") - ${before[$i]}))") s of CPU during the job"
    i=$((i + 1))
  done
}

members="127.0.0.1:$cluster,127.0.0.1:$((cluster + 1))"
for round in $(seq "$rounds"); do
  echo "round $round: one member on core 0"
  start 0 0
  until_true 300 members_up 1
  echo " cold:"; run_job
  echo " warm:"; run_job
  stop_all
  echo "round $round: two members on cores 0 and 1"
  start 0 0 --studio.cluster.port="$cluster" --studio.cluster.members="$members" --studio.cluster.bind-address=127.0.0.1
  start 1 1 --studio.cluster.port=$((cluster + 1)) --studio.cluster.members="$members" --studio.cluster.bind-address=127.0.0.1
  until_true 300 members_up 2
  echo " cold:"; run_job
  echo " warm:"; run_job
  stop_all
done
