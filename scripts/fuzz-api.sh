#!/usr/bin/env bash
# Fuzzes the API against its own OpenAPI document (/v3/api-docs) with schemathesis.
#
# Starts the jar (built when missing or older than the sources) on a free local port with small
# render limits, so that valid generated scenes render in milliseconds, waits for /actuator/health,
# and runs schemathesis over every operation with valid and invalid data. It fails on any 5xx, on
# a response that breaks the document (status code, content type, headers, body schema), on
# invalid data that is accepted, and on a 4xx that is not an application/problem+json problem (a
# scene's 400 must name each bad field in `errors`; scripts/fuzz_checks.py). Then it checks the
# service is still healthy and that it logged no error, prints the figures and stops it.
#
#   scripts/fuzz-api.sh                 # about 4,000 requests, 2-3 minutes with the jar build
#   FUZZ_MAX_EXAMPLES=300 FUZZ_SEED=7 scripts/fuzz-api.sh
#
# Needs Python 3 with venv, Java 17+ and Maven (to build the jar). Not part of the test command.
set -euo pipefail
cd "$(dirname "$0")/.."
script_started=$(date +%s)

SCHEMATHESIS_VERSION=4.32.5
MAX_EXAMPLES=${FUZZ_MAX_EXAMPLES:-100}
SEED=${FUZZ_SEED:-20261122}
CACHE=.cache
VENV=$CACHE/fuzz-venv
OUT=$CACHE/fuzz-report
JAR=backend/server/target/studio.jar

# --- schemathesis, pinned, in a virtualenv of its own -------------------------------------------
if [ ! -x "$VENV/bin/st" ] || [ "$("$VENV/bin/st" --version 2>/dev/null)" != "st, version $SCHEMATHESIS_VERSION" ]; then
  echo "installing schemathesis $SCHEMATHESIS_VERSION into $VENV"
  python3 -m venv "$VENV"
  "$VENV/bin/pip" install -q --disable-pip-version-check "schemathesis==$SCHEMATHESIS_VERSION"
fi

# --- the jar, built without the editor when missing or stale ---------------------------------------
if [ ! -f "$JAR" ] || [ -n "$(find backend/engine/src backend/server/src backend/*/pom.xml backend/pom.xml scenes \
      -newer "$JAR" -type f -print -quit)" ]; then
  echo "building $JAR"
  ./mvnw -B -q -Dstyle.color=never -f backend/pom.xml package -pl server -am -DskipTests -DskipFrontend
fi

# --- the service, on a free port, with small limits ------------------------------------------------
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
base="http://127.0.0.1:$port"
rm -rf "$OUT" && mkdir -p "$OUT"
log="$OUT/server.log"
STUDIO_LIMITS_MAXWIDTH=64 STUDIO_LIMITS_MAXHEIGHT=64 STUDIO_LIMITS_MAXSAMPLES=4 STUDIO_LIMITS_MAXDEPTH=4 \
STUDIO_LIMITS_MAXOBJECTS=50 STUDIO_LIMITS_MAXLIGHTS=8 STUDIO_LIMITS_MAXTRIANGLES=10000 \
STUDIO_LIMITS_MAXBODYBYTES=1048576 STUDIO_RENDERTHREADS=1 \
  java -Xmx1g -jar "$JAR" --server.address=127.0.0.1 --server.port="$port" >"$log" 2>&1 &
server_pid=$!
trap 'kill "$server_pid" 2>/dev/null || true; wait "$server_pid" 2>/dev/null || true' EXIT

healthy() {
  curl -fsS --max-time 5 "$base/actuator/health" 2>/dev/null | grep -q '"status":"UP"'
}
for _ in $(seq 1 120); do
  healthy && break
  kill -0 "$server_pid" 2>/dev/null || { echo "the service did not start:" >&2; tail -n 30 "$log" >&2; exit 1; }
  sleep 0.5
done
healthy || { echo "the service was not healthy after 60 s" >&2; exit 1; }
curl -fsS "$base/v3/api-docs" >"$OUT/openapi.json"
echo "service up at $base (pid $server_pid); fuzzing with seed $SEED, up to $MAX_EXAMPLES examples an operation"

# --- schemathesis -------------------------------------------------------------------------------
# one worker: with two, schemathesis 4.32.5 once crashed generating a scene (CPython
# "SystemError: AST constructor recursion depth mismatch"), and the seed fixes the order only then
started=$(date +%s)
set +e
SCHEMATHESIS_HOOKS=fuzz_checks PYTHONPATH=scripts HYPOTHESIS_STORAGE_DIRECTORY="$CACHE/hypothesis" \
  "$VENV/bin/st" --config-file scripts/schemathesis.toml run "$base/v3/api-docs" \
  --phases examples,coverage,fuzzing,stateful --mode all \
  --max-examples "$MAX_EXAMPLES" --seed "$SEED" --workers 1 --request-timeout 30 \
  --generation-database none --no-color \
  --report junit,vcr --report-vcr-path "$OUT/cassette.yaml" --report-junit-path "$OUT/junit.xml" \
  | tee "$OUT/schemathesis.txt"
st_status=${PIPESTATUS[0]}
set -e
elapsed=$(( $(date +%s) - started ))

# --- afterwards: still healthy, nothing unexpected logged, the figures ------------------------------
failed=0
if healthy; then echo "health after the run: UP"; else echo "health after the run: NOT UP" >&2; failed=1; fi
errors=$(grep -c ' ERROR ' "$log" || true)
echo "errors logged by the service: $errors"
[ "$errors" -eq 0 ] || { grep -m 5 -A 3 ' ERROR ' "$log" >&2; failed=1; }
echo "schemathesis: exit code $st_status, $elapsed s"
[ "$st_status" -eq 0 ] || failed=1
if [ -f "$OUT/cassette.yaml" ]; then
  "$VENV/bin/python" scripts/fuzz_checks.py "$OUT/cassette.yaml" "$OUT/openapi.json" || failed=1
else
  echo "no cassette was recorded" >&2
  failed=1
fi
echo "report: $OUT (schemathesis.txt, cassette.yaml, junit.xml, openapi.json, server.log)"
echo "the whole script: $(( $(date +%s) - script_started )) s"
if [ "$failed" -ne 0 ]; then
  echo "FUZZ FAILED" >&2
  exit 1
fi
echo "FUZZ PASSED"
