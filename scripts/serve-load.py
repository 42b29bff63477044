#!/usr/bin/env python3
"""Loads `foldkit serve` with concurrent clients and counts the answers (docs/SERVE.md, *Under load*).

    python3 scripts/serve-load.py [--foldkit build/apps/foldkit] [--clients 24] [--requests 12]
                                  [--rows 10] [--cols 10] [-- SERVE OPTION…]
    python3 scripts/serve-load.py --url http://127.0.0.1:8080 --pattern m10.pmml --sequence m10-folded.cmml

Each client sends its requests one after the other on a new connection each, a third each
`GET /api`, `POST /api/info` and `POST /api/simulate` (client c's request j is kind (c + j) % 3).
Without --url it generates a Miura-ori ROWS × COLS and its fold to 0.5 in a temporary root (removed
at the end) and starts `FOLDKIT serve --port 0` there (options after `--` go to serve, e.g. `-- --workers 1`).
Prints, per kind, how many requests got each HTTP status (0: no answer: refused connection,
reset, or no answer within --timeout), the median and longest time to an answer, whether every
503 carried Retry-After, and the wall time.
Exit 0 when every request got an answer, 1 otherwise. Python's standard library only.
"""
import argparse
import collections
import http.client
import json
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import time
import urllib.parse

KINDS = ("GET /api", "info", "simulate")


def one_request(host, port, kind, pattern, sequence, timeout):
    """(status, Retry-After or None); status 0 when no answer came."""
    try:
        c = http.client.HTTPConnection(host, port, timeout=timeout)
        if kind == 0:
            c.request("GET", "/api")
        else:
            body = {"pattern": pattern} if kind == 1 else {"pattern": pattern, "sequence": sequence}
            verb = "info" if kind == 1 else "simulate"
            c.request("POST", "/api/" + verb, json.dumps(body), {"Content-Type": "application/json"})
        r = c.getresponse()
        r.read()
        c.close()
        return r.status, r.getheader("Retry-After")
    except (OSError, http.client.HTTPException):
        return 0, None


def run_load(host, port, clients, requests, pattern, sequence, timeout):
    tally = collections.Counter()  # (kind, status) → requests
    durations = collections.defaultdict(list)  # kind → seconds of each answered request
    retry_missing = 0
    lock = threading.Lock()

    def client(c):
        nonlocal retry_missing
        for j in range(requests):
            kind = (c + j) % 3
            sent = time.monotonic()
            status, retry = one_request(host, port, kind, pattern, sequence, timeout)
            with lock:
                tally[(kind, status)] += 1
                if status:
                    durations[kind].append(time.monotonic() - sent)
                if status == 503 and not (retry and retry.isdigit()):
                    retry_missing += 1

    threads = [threading.Thread(target=client, args=(c,)) for c in range(clients)]
    start = time.monotonic()
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    return tally, durations, retry_missing, time.monotonic() - start


def start_server(foldkit, rows, cols, serve_options):
    root = tempfile.mkdtemp(prefix="foldkit-serve-load-")
    pattern, sequence = "m.pmml", "m-folded.cmml"
    subprocess.run([foldkit, "generate", "miura", "--rows", str(rows), "--cols", str(cols), "-o", os.path.join(root, pattern)],
                   check=True, capture_output=True)
    subprocess.run([foldkit, "fold", os.path.join(root, pattern), "--fraction", "0.5", "-o", os.path.join(root, sequence)],
                   check=True, capture_output=True)
    server = subprocess.Popen([foldkit, "serve", "--port", "0", "--root", root, "--web", ""] + serve_options,
                              stderr=subprocess.PIPE, text=True)
    line = server.stderr.readline()  # foldkit serve: http://127.0.0.1:PORT/api (root …); Ctrl-C stops it
    if "http://" not in line:
        server.kill()
        sys.exit("serve-load: the server did not start: " + line.strip())
    url = urllib.parse.urlparse(line.split()[2])
    return server, root, url.hostname, url.port, pattern, sequence


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--foldkit", default="build/apps/foldkit", help="the CLI to start serve from (without --url)")
    p.add_argument("--url", help="a running server instead (its root must hold --pattern and --sequence)")
    p.add_argument("--pattern", default="m10.pmml")
    p.add_argument("--sequence", default="m10-folded.cmml")
    p.add_argument("--clients", type=int, default=24)
    p.add_argument("--requests", type=int, default=12, help="requests per client")
    p.add_argument("--rows", type=int, default=10)
    p.add_argument("--cols", type=int, default=10)
    p.add_argument("--timeout", type=float, default=120, help="seconds a client waits for an answer")
    p.add_argument("serve_options", nargs="*", help="after --: options of foldkit serve")
    a = p.parse_args()

    server = root = None
    if a.url:
        url = urllib.parse.urlparse(a.url)
        host, port, pattern, sequence = url.hostname, url.port or 80, a.pattern, a.sequence
    else:
        server, root, host, port, pattern, sequence = start_server(a.foldkit, a.rows, a.cols, a.serve_options)
    try:
        tally, durations, retry_missing, seconds = run_load(host, port, a.clients, a.requests, pattern, sequence, a.timeout)
    finally:
        if server:
            server.terminate()
            server.wait()
            shutil.rmtree(root, ignore_errors=True)
    sent = sum(tally.values())
    print(f"{a.clients} clients x {a.requests} requests = {sent} in {seconds:.1f} s")
    for kind, name in enumerate(KINDS):
        counts = {s: n for (k, s), n in sorted(tally.items()) if k == kind}
        times = sorted(durations[kind])
        spread = f"; answered in {times[len(times) // 2]:.2f} s median, {times[-1]:.2f} s at most" if times else ""
        print(f"  {name:9} " + ", ".join(f"{n} x {s if s else 'no answer'}" for s, n in counts.items()) + spread)
    total = collections.Counter()
    for (_, s), n in tally.items():
        total[s] += n
    print("  all       " + ", ".join(f"{n} x {s if s else 'no answer'}" for s, n in sorted(total.items())))
    if total[503]:
        print(f"  503 without Retry-After: {retry_missing}")
    return 0 if total[0] == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
