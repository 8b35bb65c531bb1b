#!/usr/bin/env python3
"""Two pinned members against one service, by CPU (docs/cluster.md, "Pinned, on a quiet machine"): one plain service pinned
to core 0, then two members pinned to cores 0 and 1 (--studio.render-threads=1), each start renders the job cold
then warm. Records each job's wall time (status elapsedMillis) and the CPU of each thread during the job from
/proc/<pid>/task/*/stat, split into tile workers, compiler threads, Hazelcast threads and other (threads that
ended during the job count under 'gone': one service's render threads). Prints a line per job and appends it
to --out as JSON; the busier member's CPU against one service's is the ratio to expect on idle cores.

  scripts/cluster-cpu.py --jar backend/server/target/studio.jar --scene JOB.json [--label L]
      [--mode both|single|pair|alternate] [--jobs 2] [--rounds 4] [--jvm=OPT]... [--arg=ARG]...
      alternate: the one service and the two members all started at once (the service and the first member
      share core 0; a JVM without a job only idles), then their jobs alternate, single and pair cold, then
      --rounds rounds of warm jobs, pair and single in turns (ABBA), so that each pair of jobs compared ran
      seconds apart: this machine's speed drifts by a third within minutes, which --mode both puts between
      the one service's start and the members'.
  scripts/cluster-cpu.py --summary [--out FILE]   medians and ranges per scene, label and phase: the busier
      member against the same start's one service, and the pair's CPU beyond its tile workers'
"""
import argparse, json, os, signal, subprocess, sys, time, urllib.request, base64, glob

TICK = os.sysconf('SC_CLK_TCK')

def threads(pid):
    out = {}
    for d in glob.glob('/proc/%d/task/*' % pid):
        try:
            s = open(d + '/stat').read()
        except OSError:
            continue
        name = s[s.index('(') + 1:s.rindex(')')]
        f = s[s.rindex(')') + 2:].split()
        out[int(d.rsplit('/', 1)[1])] = (name, (int(f[11]) + int(f[12])) / TICK)
    return out

def proc_cpu(pid):
    s = open('/proc/%d/stat' % pid).read()
    f = s[s.rindex(')') + 2:].split()
    return (int(f[11]) + int(f[12])) / TICK

def kind(name):
    if name.startswith('tile-worker') or (name.startswith('render-') and not name.startswith('render-job')):
        return 'tiles'
    if 'CompilerThre' in name or name.startswith('C1 ') or name.startswith('C2 '):
        return 'compiler'
    if name.startswith('hz.') or 'hz.' in name:
        return 'hazelcast'
    return 'other'

def split(pid, before, total_before):
    after = threads(pid)
    parts = {'tiles': 0.0, 'compiler': 0.0, 'hazelcast': 0.0, 'other': 0.0}
    names = {}
    for tid, (name, cpu) in after.items():
        d = cpu - before.get(tid, (name, 0.0))[1]
        parts[kind(name)] += d
        names[name] = names.get(name, 0.0) + d
    total = proc_cpu(pid) - total_before
    parts['gone'] = total - sum(parts.values())
    parts['all'] = total
    return parts, names

def get(url):
    with urllib.request.urlopen(url, timeout=10) as r:
        return r.read()

def post(url, body):
    req = urllib.request.Request(url, data=body, headers={'Content-Type': 'application/json'})
    with urllib.request.urlopen(req, timeout=30) as r:
        return json.loads(r.read())

def members(port):
    try:
        for line in get('http://127.0.0.1:%d/actuator/prometheus' % port).decode().splitlines():
            if line.startswith('studio_cluster_members'):
                return float(line.split()[-1])
        return 1.0  # plain service: up
    except Exception:
        return 0.0

def start(args, core, i, extra, log):
    cmd = ['taskset', '-c', str(core), args.java, '-Xmx1g'] + [o.replace('{i}', str(i)) for o in args.jvm] + \
          ['-jar', args.jar, '--server.port=%d' % (args.http + i), '--studio.render-threads=1'] + args.arg + extra
    return subprocess.Popen(cmd, stdout=open(log, 'w'), stderr=subprocess.STDOUT, start_new_session=True)

def job(args, pids, scene, port=None):
    port = port or args.http
    befores = [(threads(p), proc_cpu(p)) for p in pids]
    t0 = time.time()
    jid = post('http://127.0.0.1:%d/api/jobs' % port, scene)['id']
    while True:
        time.sleep(0.2)
        st = json.loads(get('http://127.0.0.1:%d/api/jobs/%s' % (port, jid)))
        if st['state'] in ('done', 'failed', 'cancelled'):
            break
        if time.time() - t0 > 1200:
            raise SystemExit('job timed out')
    res = {'t0': t0, 't1': time.time(), 'state': st['state'], 'ms': st.get('elapsedMillis'), 'workers': st.get('workers'), 'members': []}
    for p, (b, tb) in zip(pids, befores):
        parts, names = split(p, b, tb)
        res['members'].append({'parts': parts, 'top': sorted(names.items(), key=lambda kv: -kv[1])[:8]})
    return res

def fmt(r):
    ms = [m['parts'] for m in r['members']]
    tot = {k: sum(m[k] for m in ms) for k in ms[0]}
    busier = max(m['all'] for m in ms)
    return ('%s %6d ms  all %5.2f busier %5.2f | tiles %5.2f compiler %5.2f hz %5.2f other %5.2f gone %5.2f  %s'
            % (r['state'], r['ms'] or -1, tot['all'], busier, tot['tiles'], tot['compiler'], tot['hazelcast'],
               tot['other'], tot['gone'], r['workers'] or ''))

def summary(out):
    import statistics
    rows = [json.loads(line) for line in open(out)]
    def span(xs):
        return '%.3f (%.3f-%.3f)' % (statistics.median(xs), min(xs), max(xs)) if xs else '-'
    for scene in sorted({r['scene'] for r in rows}):
        for label in sorted({r['label'] for r in rows}):
            for phase in ('cold', 'warm'):
                single = [r for r in rows if (r['scene'], r['label'], r['phase'], r['kind']) == (scene, label, phase, 'single')]
                pairs = [r for r in rows if (r['scene'], r['label'], r['phase'], r['kind']) == (scene, label, phase, 'pair')]
                if not pairs:
                    continue
                ratio, wall, beyond, hz, compiler, loads = [], [], [], [], [], []
                for i, r in enumerate(pairs):
                    ms = [m['parts'] for m in r['members']]
                    total = {k: sum(m[k] for m in ms) for k in ms[0]}
                    beyond.append(total['all'] - total['tiles'])
                    hz.append(total['hazelcast'])
                    compiler.append(total['compiler'])
                    loads.append(float(r['load']))
                    if i < len(single):  # the one service of the same start (alternate: the job beside it)
                        ratio.append(max(m['all'] for m in ms) / single[i]['members'][0]['parts']['all'])
                        if r['ms'] and single[i]['ms']:
                            wall.append(r['ms'] / single[i]['ms'])
                print('%s %s %s n=%d: wall pair/one %s | busier/one %s | beyond the tiles %s | hazelcast %s | compiler %s | load %.0f-%.0f'
                      % (scene, label, phase, len(pairs), span(wall), span(ratio), span(beyond), span(hz), span(compiler),
                         min(loads), max(loads)))

def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--jar')
    ap.add_argument('--scene')
    ap.add_argument('--summary', action='store_true')
    ap.add_argument('--label', default='')
    ap.add_argument('--mode', default='both')
    ap.add_argument('--java', default='java')
    ap.add_argument('--jvm', action='append', default=[])
    ap.add_argument('--arg', action='append', default=[])
    ap.add_argument('--http', type=int, default=8390)
    ap.add_argument('--cluster', type=int, default=5890)
    ap.add_argument('--jobs', type=int, default=2)
    ap.add_argument('--rounds', type=int, default=4)
    ap.add_argument('--out', default='backend/server/target/cluster-cpu.jsonl')
    ap.add_argument('--logs', default='backend/server/target/cluster-cpu-logs')
    args = ap.parse_args()
    if args.summary:
        summary(args.out)
        return
    if not args.jar or not args.scene:
        ap.error('--jar and --scene are needed')
    os.makedirs(args.logs, exist_ok=True)
    scene = open(args.scene, 'rb').read()
    env_secret = os.environ.setdefault('STUDIO_CLUSTER_SECRET', base64.b64encode(os.urandom(48)).decode())
    if args.mode == 'alternate':
        alternate(args, scene)
        return
    runs = []
    if args.mode in ('both', 'single'):
        runs.append(('single', [(0, 0, [])]))
    if args.mode in ('both', 'pair'):
        mem = '127.0.0.1:%d,127.0.0.1:%d' % (args.cluster, args.cluster + 1)
        common = ['--studio.cluster.members=' + mem, '--studio.cluster.bind-address=127.0.0.1']
        runs.append(('pair', [(0, 0, ['--studio.cluster.port=%d' % args.cluster] + common),
                              (1, 1, ['--studio.cluster.port=%d' % (args.cluster + 1)] + common)]))
    for kindname, specs in runs:
        procs = []
        try:
            for core, i, extra in specs:
                procs.append(start(args, core, i, extra, '%s/%s-%s-%d.log' % (args.logs, args.label, kindname, i)))
            want = len(specs) if kindname == 'pair' else 1
            t0 = time.time()
            while members(args.http) < want or any(members(args.http + i) < want for _, i, _ in specs):
                if time.time() - t0 > 400:
                    raise SystemExit('members not up')
                time.sleep(0.5)
            load = open('/proc/loadavg').read().split()[0]
            for phase in ['cold', 'warm'] + ['warm%d' % k for k in range(2, args.jobs)]:
                r = job(args, [p.pid for p in procs], scene)
                r.update(label=args.label, kind=kindname, phase=phase, load=load, scene=os.path.basename(args.scene),
                         time=time.strftime('%H:%M:%S'))
                open(args.out, 'a').write(json.dumps(r) + '\n')
                print('%-10s %-6s %-4s load %s  %s' % (args.label, kindname, phase, load, fmt(r)), flush=True)
                load = open('/proc/loadavg').read().split()[0]
        finally:
            stop(procs)

def stop(procs):
    for p in procs:
        try:
            os.killpg(p.pid, signal.SIGTERM)
        except ProcessLookupError:
            pass
    for p in procs:
        try:
            p.wait(30)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait()

def alternate(args, scene):
    """The one service (HTTP port --http, core 0) and two members (--http + 1 and + 2, cores 0 and 1) at once."""
    mem = '127.0.0.1:%d,127.0.0.1:%d' % (args.cluster, args.cluster + 1)
    common = ['--studio.cluster.members=' + mem, '--studio.cluster.bind-address=127.0.0.1']
    log = lambda name: '%s/%s-alternate-%s.log' % (args.logs, args.label, name)
    procs = []
    try:
        procs.append(start(args, 0, 0, [], log('single')))
        procs.append(start(args, 0, 1, ['--studio.cluster.port=%d' % args.cluster] + common, log('member-1')))
        procs.append(start(args, 1, 2, ['--studio.cluster.port=%d' % (args.cluster + 1)] + common, log('member-2')))
        single, pair = procs[0], procs[1:]
        t0 = time.time()
        while members(args.http) < 1 or members(args.http + 1) < 2 or members(args.http + 2) < 2:
            if time.time() - t0 > 600:
                raise SystemExit('services not up')
            time.sleep(0.5)
        kinds = {'single': ([single.pid], args.http), 'pair': ([p.pid for p in pair], args.http + 1)}
        order = [('single', 'cold'), ('pair', 'cold')]
        for k in range(args.rounds):
            first, second = ('pair', 'single') if k % 2 == 0 else ('single', 'pair')
            order += [(first, 'warm'), (second, 'warm')]
        for kindname, phase in order:
            load = open('/proc/loadavg').read().split()[0]
            pids, port = kinds[kindname]
            r = job(args, pids, scene, port)
            r.update(label=args.label, kind=kindname, phase=phase, load=load, scene=os.path.basename(args.scene),
                     time=time.strftime('%H:%M:%S'))
            open(args.out, 'a').write(json.dumps(r) + '\n')
            print('%-10s %-6s %-4s load %s  %s' % (args.label, kindname, phase, load, fmt(r)), flush=True)
    finally:
        stop(procs)

if __name__ == '__main__':
    main()
