#!/usr/bin/env python3
"""What an embedded cluster member costs: a service started as its own one member against one without
members, alternated ROUNDS times (default 3): start-up (Spring's "Started" figure and until
/actuator/health answers), 25 jobs of the still life at 320x240 and 4 samples one after another (the
median latency of the last 20, submit to done), then heap used after a full GC (/actuator/prometheus),
resident memory and threads. Needs the jar (./mvnw -B -q -f backend/pom.xml package -DskipTests), jcmd,
and HTTP port 8395 and cluster port 5795 free.

    scripts/member-cost.py [ROUNDS]
"""
import subprocess, time, json, urllib.request, re, statistics, os, sys
ROOT=os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
JAR=os.environ.get('STUDIO_JAR', os.path.join(ROOT,'backend/server/target/studio.jar'))
SCENE=open(os.path.join(ROOT,'scenes/still-life.json')).read()
sc=json.loads(SCENE); sc['image'].update(width=320,height=240); sc['render']['samples']=4
BODY=json.dumps(sc).encode()
def get(url):
    return urllib.request.urlopen(url, timeout=10).read()
def run(kind, port):
    args=['java','-Xmx1g','-jar',JAR,f'--server.port={port}']
    if kind=='member':
        args+=['--studio.cluster.members=127.0.0.1:5795','--studio.cluster.port=5795','--studio.cluster.bind-address=127.0.0.1']
    log=open(f'/tmp/mc-{kind}.log','w')
    p=subprocess.Popen(args, stdout=log, stderr=subprocess.STDOUT)
    t0=time.time()
    while True:
        try:
            get(f'http://127.0.0.1:{port}/actuator/health'); break
        except Exception: time.sleep(0.2)
    up=time.time()-t0
    lat=[]
    for i in range(25):
        t=time.time()
        req=urllib.request.Request(f'http://127.0.0.1:{port}/api/jobs', data=BODY, headers={'Content-Type':'application/json'})
        jid=json.loads(urllib.request.urlopen(req).read())['id']
        while json.loads(get(f'http://127.0.0.1:{port}/api/jobs/{jid}'))['state'] not in ('done','failed','cancelled'):
            time.sleep(0.01)
        lat.append(time.time()-t)
    subprocess.run(['jcmd',str(p.pid),'GC.run'],capture_output=True)
    time.sleep(1)
    prom=get(f'http://127.0.0.1:{port}/actuator/prometheus').decode()
    heap=sum(float(m) for m in re.findall(r'^jvm_memory_used_bytes\{area="heap".*\} (\S+)$', prom, re.M))
    rss=int(open(f'/proc/{p.pid}/status').read().split('VmRSS:')[1].split()[0])/1024
    threads=len(os.listdir(f'/proc/{p.pid}/task'))
    started=re.search(r'Started StudioApplication in ([\d.]+) seconds', open(f'/tmp/mc-{kind}.log').read())
    p.terminate(); p.wait()
    return dict(kind=kind, started=float(started.group(1)) if started else None, up=round(up,2), job_ms_median=round(1000*statistics.median(lat[5:]),1), heap_mb=round(heap/2**20,1), rss_mb=round(rss,1), threads=threads)
for r in range(int(sys.argv[1]) if len(sys.argv) > 1 else 3):
    for kind in ('single','member'):
        print(run(kind, 8395), flush=True)
