#!/usr/bin/env bash
# Load test on loopback: builds studio.jar if missing, starts it with its default configuration on
# a free port (the metrics endpoint exposed for this run only), runs scripts/LoadTest.java against
# it and stops it. Exit code: the load test's (0 when every check passed). The server's log is kept
# in backend/server/target/load-test-server.log. STUDIO_JAR=path tests another jar.
#
# Sign-in: STUDIO_API_KEYS=NAME:KEY,NAME:KEY,... starts the server with
# --studio.security.api-keys=... and hands the keys, in that order, to LoadTest.java (--keys): client i
# signs in with key i mod n, and --greedy N clients with the first one. STUDIO_SERVER_ARGS adds
# arguments to the server's command line (split on spaces), e.g.
# STUDIO_SERVER_ARGS=--studio.security.max-jobs-per-principal=100 to put the per-principal limit out of reach.
#
#   scripts/load-test.sh [--clients 50] [--seconds 60] [other LoadTest.java options]
#   STUDIO_API_KEYS=greedy:KEY1,alice:KEY2,bob:KEY3 scripts/load-test.sh --clients 20 --greedy 10 --seconds 30
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
jar="${STUDIO_JAR:-$root/backend/server/target/studio.jar}"
java="${JAVA:-java}"
log="$root/backend/server/target/load-test-server.log"

if [[ ! -f "$jar" ]]; then
  echo "building $jar"
  "$root/mvnw" -B -q -f "$root/backend/pom.xml" package -pl server -am -DskipTests -DskipFrontend
fi

server_args=(--server.port=0)
test_args=()
if [[ -n "${STUDIO_API_KEYS:-}" ]]; then
  server_args+=("--studio.security.api-keys=$STUDIO_API_KEYS")
  keys=""
  IFS=',' read -ra pairs <<<"$STUDIO_API_KEYS"
  for pair in "${pairs[@]}"; do
    keys+="${keys:+,}${pair#*:}"
  done
  test_args+=(--keys "$keys")
fi
read -ra extra <<<"${STUDIO_SERVER_ARGS:-}"
server_args+=("${extra[@]}")

# port 0: the server takes a free port and logs it
MANAGEMENT_ENDPOINTS_WEB_EXPOSURE_INCLUDE=health,info,metrics \
  "$java" -jar "$jar" "${server_args[@]}" >"$log" 2>&1 &
pid=$!
stop() {
  kill "$pid" 2>/dev/null && wait "$pid" 2>/dev/null || true
}
trap stop EXIT

port=""
for _ in $(seq 600); do
  port="$(sed -n 's/.*Tomcat started on port \([0-9]*\).*/\1/p' "$log" | head -1)"
  [[ -z "$port" ]] && kill -0 "$pid" 2>/dev/null || break
  sleep 0.1
done
if [[ -z "$port" ]]; then
  echo "error: the server did not start; its log:" >&2
  tail -20 "$log" >&2
  exit 1
fi
echo "server pid $pid on port $port (log: $log)"
status=0
"$java" "$root/scripts/LoadTest.java" --url "http://127.0.0.1:$port" --pid "$pid" --scenes "$root/scenes" \
  "${test_args[@]}" "$@" \
  || status=$?
if grep -q ' ERROR ' "$log"; then
  echo "the server logged errors:"
  grep -A3 ' ERROR ' "$log" | head -40
  [[ $status -ne 0 ]] || status=1
fi
exit "$status"
