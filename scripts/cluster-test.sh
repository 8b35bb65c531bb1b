#!/usr/bin/env bash
# Three cluster members on loopback, each its own JVM; a render job submitted to the first and read through
# the second; a worker (the third) and then the member that accepted the job (the first) killed with SIGKILL
# mid-render; the job must end done through the second member, with the same image bytes as one member's
# synchronous render of the same scene (POST /api/render). Builds studio.jar if missing (STUDIO_JAR=path tests
# another). Logs: backend/server/target/cluster-test-member-N.log. Exit code 0 when every check passed.
#
#   scripts/cluster-test.sh [--http-port 8290] [--cluster-port 5790] [--scene FILE]
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
jar="${STUDIO_JAR:-$root/backend/server/target/studio.jar}"
java="${JAVA:-java}"
http=8290
cluster=5790
scene=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --http-port) http="$2"; shift 2 ;;
    --cluster-port) cluster="$2"; shift 2 ;;
    --scene) scene="$2"; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
work="$(mktemp -d)"
# the members' shared secret (a clustered member refuses to start without one)
export STUDIO_CLUSTER_SECRET="${STUDIO_CLUSTER_SECRET:-$(openssl rand -base64 48)}"
if [[ -z "$scene" ]]; then
  scene="$work/scene.json"
  cat >"$scene" <<'JSON'
{"name": "cluster-test", "image": {"width": 640, "height": 480, "format": "png"},
 "camera": {"position": [0, 1.2, 5], "lookAt": [0, 0.5, 0]},
 "render": {"sampler": "jittered", "samples": 192, "maxDepth": 8, "seed": 7},
 "objects": [{"type": "sphere", "center": [-0.6, 0.5, 0], "radius": 0.5, "material": {"type": "glass"}},
             {"type": "sphere", "center": [0.6, 0.5, 0], "radius": 0.5, "material": {"type": "mirror"}},
             {"type": "plane"}]}
JSON
fi

if [[ ! -f "$jar" ]]; then
  echo "building $jar"
  "$root/mvnw" -B -q -f "$root/backend/pom.xml" package -pl server -am -DskipTests -DskipFrontend
fi

members="127.0.0.1:$cluster,127.0.0.1:$((cluster + 1)),127.0.0.1:$((cluster + 2))"
pids=()
stop() {
  for pid in "${pids[@]}"; do kill -9 "$pid" 2>/dev/null || true; done
  rm -rf "$work"
}
trap stop EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

url() { echo "http://127.0.0.1:$((http + $1))"; }

# field NAME of the JSON on stdin (top level, or details.members of the health)
field() { python3 -c "import json,sys; d=json.load(sys.stdin); print(eval('d' + sys.argv[1]))" "$1"; }

# until SECONDS CONDITION...: runs the condition every 0.2 s until it holds, at most SECONDS
until_true() {
  local seconds=$1; shift
  local deadline=$((SECONDS + seconds))
  until "$@"; do
    [[ $SECONDS -lt $deadline ]] || return 1
    sleep 0.2
  done
}

for i in 0 1 2; do
  # one render thread each: three members share this machine's cores
  "$java" -Xmx1g -jar "$jar" --server.port=$((http + i)) --studio.cluster.port=$((cluster + i)) \
    --studio.cluster.members="$members" --studio.cluster.bind-address=127.0.0.1 --studio.render-threads=1 \
    >"$root/backend/server/target/cluster-test-member-$i.log" 2>&1 &
  pids+=($!)
done
three_members() {
  for i in 0 1 2; do
    # the health's details go to signed-in callers only (docs/security.md); the metric is open with sign-in off
    [[ "$(curl -fsS "$(url $i)/actuator/prometheus" 2>/dev/null \
          | sed -n 's/^studio_cluster_members\({[^}]*}\)\{0,1\} \([0-9]*\).*/\2/p' | head -1)" == 3 ]] \
      || return 1
  done
}
until_true 180 three_members || fail "the three members did not form a cluster within 180 s"
echo "three members up: $members"

echo "one member's image: POST /api/render to member 0"
start=$SECONDS
curl -fsS -o "$work/one.png" -H 'Content-Type: application/json' --data-binary "@$scene" "$(url 0)/api/render" \
  || fail "POST /api/render failed"
echo "  $((SECONDS - start)) s, $(stat -c %s "$work/one.png") bytes"

id="$(curl -fsS -H 'Content-Type: application/json' --data-binary "@$scene" "$(url 0)/api/jobs" | field "['id']")"
echo "job $id accepted by member 0; reading it through member 1"
curl -sN --max-time 600 "$(url 1)/api/jobs/$id/events" >"$work/events.txt" 2>/dev/null &
status() { curl -fsS "$(url 1)/api/jobs/$id"; }
worker_rendered() {
  [[ "$(status | field ".get('workers', {}).get('127.0.0.1:$((cluster + 2))', 0)" 2>/dev/null)" -gt 0 ]]
}
until_true 120 worker_rendered || fail "member 2 rendered no tile within 120 s"
echo "  $(status)"
echo "SIGKILL member 2 (a worker)"
kill -9 "${pids[2]}"
wait "${pids[2]}" 2>/dev/null || true

progressed() { python3 -c "import sys; sys.exit(0 if float(sys.argv[1]) >= 0.3 else 1)" "$(status | field "['progress']")"; }
until_true 300 progressed || fail "the job did not reach 30% within 300 s"
echo "  $(status)"
[[ "$(status | field "['state']")" == running ]] || fail "the job is not running any more: $(status)"
echo "SIGKILL member 0 (the member that accepted the job)"
kill -9 "${pids[0]}"
wait "${pids[0]}" 2>/dev/null || true

ended() { [[ "$(status | field "['state']")" =~ ^(done|failed|cancelled)$ ]]; }
until_true 600 ended || fail "the job did not end within 600 s after member 0 died"
echo "  $(status)"
[[ "$(status | field "['state']")" == done ]] || fail "the job ended $(status)"
curl -fsS -o "$work/cluster.png" "$(url 1)/api/jobs/$id/image" || fail "no image through member 1"
cmp "$work/one.png" "$work/cluster.png" || fail "the cluster's image differs from one member's"
echo "the image through member 1 is byte for byte one member's ($(stat -c %s "$work/cluster.png") bytes)"
until_true 30 grep -q '^event:end' "$work/events.txt" || fail "the event stream through member 1 did not end"
echo "the event stream through member 1: $(grep -c '^event:tile' "$work/events.txt") tile events, then the end"
echo "PASS"
