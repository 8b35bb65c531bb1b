"""Ray Studio's own rules for scripts/fuzz-api.sh, in two parts.

As a schemathesis hook module (SCHEMATHESIS_HOOKS=fuzz_checks), a check that runs on every
response: an error of the API (4xx) is an RFC 9457 problem (application/problem+json) whose
`status` is the response's, and a 400 for a scene body carries `errors`, each naming a field by
its JSON path (empty for the body as a whole) with a message.

As a program (`python fuzz_checks.py CASSETTE OPENAPI_JSON`), it reads the VCR cassette of the run
and prints the figures: requests sent, status codes, requests per operation, and the same rules
checked over every recorded response.
"""

import json
import sys
from collections import Counter

SCENE_OPERATIONS = {("POST", "/api/render"), ("POST", "/api/jobs")}
PROBLEM_JSON = "application/problem+json"


def problem_violations(method, path, status, content_type, body):
    """What is wrong with one response by Ray Studio's rules (an empty list when nothing is)."""
    if not 400 <= status < 500 or not path.startswith("/api/"):
        return []
    if not (content_type or "").startswith(PROBLEM_JSON):
        return [f"{status} is {content_type or 'without a content type'}, not {PROBLEM_JSON}"]
    try:
        problem = json.loads(body)
    except ValueError:
        return [f"{status} problem body is not JSON: {body[:200]!r}"]
    if not isinstance(problem, dict):
        return [f"{status} problem body is not a JSON object"]
    wrong = []
    if problem.get("status") != status:
        wrong.append(f"problem status {problem.get('status')!r} differs from the response's {status}")
    if not isinstance(problem.get("title"), str):
        wrong.append(f"{status} problem without a title")
    if status == 400 and (method, path) in SCENE_OPERATIONS:
        errors = problem.get("errors")
        if not isinstance(errors, list) or not errors:
            wrong.append("400 for a scene without a non-empty `errors` list")
        else:
            for error in errors:
                if not (isinstance(error, dict) and isinstance(error.get("field"), str)
                        and isinstance(error.get("message"), str) and error["message"]):
                    wrong.append(f"`errors` entry without a field and a message: {error!r}")
    return wrong


try:
    import schemathesis
except ImportError:  # run as the cassette reader outside the virtualenv
    schemathesis = None

if schemathesis is not None:

    @schemathesis.check
    def rejections_are_problems(ctx, response, case):
        """4xx: application/problem+json with the response's status; a scene's 400 names each bad field."""
        content_type = (response.headers.get("content-type") or [""])[0]
        wrong = problem_violations(case.method.upper(), case.operation.path, response.status_code, content_type,
                                   response.content.decode("utf-8", "replace"))
        if wrong:
            raise AssertionError("; ".join(wrong))


def summarise(cassette_path, openapi_path):
    """Prints the run's figures from its cassette; returns the number of 5xx and rule violations found."""
    import yaml  # a dependency of schemathesis

    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)  # libyaml's: ten times faster on a 10 MB cassette
    with open(cassette_path, encoding="utf-8") as f:
        interactions = yaml.load(f, Loader=loader).get("http_interactions", [])
    with open(openapi_path, encoding="utf-8") as f:
        paths = json.load(f)["paths"]
    documented = {f"{method.upper()} {path}" for path, item in paths.items() for method in item}
    statuses = Counter()
    by_operation = Counter()
    violations = []
    for interaction in interactions:
        request, response = interaction["request"], interaction.get("response")
        method = request["method"].upper()
        path = "/" + request["uri"].split("://", 1)[-1].split("/", 1)[-1].split("?", 1)[0]
        template = operation_template(path)
        operation = f"{method} {template}"
        by_operation[operation if operation in documented else "other methods"] += 1
        if response is None:
            statuses["no response"] += 1
            continue
        status = int(response["status"]["code"])
        statuses[status] += 1
        headers = {k.lower(): v for k, v in (response.get("headers") or {}).items()}
        content_type = (headers.get("content-type") or [""])[0]
        body = (response.get("body") or {}).get("string", "")
        for wrong in problem_violations(method, template, status, content_type, body):
            violations.append(f"{method} {path}: {wrong}")
    print(f"requests sent: {len(interactions)}")
    print("status codes:  " + ", ".join(f"{code}: {n}" for code, n in sorted(statuses.items(), key=lambda kv: str(kv[0]))))
    print("per operation: " + ", ".join(f"{op}: {n}" for op, n in sorted(by_operation.items())))
    server_errors = sum(n for code, n in statuses.items() if isinstance(code, int) and code >= 500)
    print(f"5xx responses: {server_errors}")
    print(f"4xx that break the problem rules: {len(violations)}")
    for wrong in violations[:20]:
        print("  " + wrong)
    return len(violations) + server_errors


def operation_template(path):
    """/api/jobs/abc/image -> /api/jobs/{id}/image, so that the counts group by operation."""
    parts = path.split("/")
    if len(parts) >= 4 and parts[1] == "api" and parts[2] == "jobs":
        parts[3] = "{id}"
    elif len(parts) >= 4 and parts[1] == "api" and parts[2] == "scenes":
        parts[3] = "{name}"
    return "/".join(parts)


if __name__ == "__main__":
    sys.exit(1 if summarise(sys.argv[1], sys.argv[2]) else 0)
