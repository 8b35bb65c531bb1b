#!/usr/bin/env python3
"""Writes the held-out scenes the speed figures are checked on (docs/speed.md, docs/cluster.md): scenes
no change is tuned on, written before the tuning they check. Seeded, so the same files every time:

  scripts/held-out.py DIR     DIR/glass-crowd.json     a glass ball and a glass box over 90 boxes
                              DIR/mirror-corridor.json two facing mirrors, 9 metal, glass and plastic balls
                              DIR/sphere-cloud.json    7,000 small spheres over a floor
                              DIR/terrain.json (.obj)  a 51,200-triangle terrain, a glass and a metal ball
                              DIR/soft/soft-blocks.json  40 boxes under a sphere light (160x120 charts)
                              DIR/soft/soft-table.json   a table with glass under an area light
                              DIR/soft/soft-city.json    32 boxes and a mirror ball under a sphere light
                              DIR/soft/soft-shelf.json   a shelf with glass and metal under a strip area light
                              DIR/cluster-job.json     960x720 at 36 jittered samples: glass, a mirror, 45 boxes
"""
import json, math, os, random, sys
if len(sys.argv) != 2:
    sys.exit(__doc__)
D = sys.argv[1]
os.makedirs(os.path.join(D, 'soft'), exist_ok=True)
R = random.Random(20261207)
def col(): return '#%02x%02x%02x' % tuple(R.randrange(60, 230) for _ in range(3))
def mat():
    k = R.random()
    if k < 0.5: return {"type": "chalk", "color": col()}
    if k < 0.8: return {"type": "plastic", "color": col()}
    if k < 0.92: return {"type": "metal", "color": col()}
    return {"type": "mirror"}
def scene(name, w, h, cam, look, fov, lights, objects, samples=16, sampler="jittered", depth=8, ambient=0.06):
    return {"version": 1, "name": name, "image": {"width": w, "height": h, "format": "png"},
            "camera": {"position": cam, "lookAt": look, "up": [0, 1, 0], "fov": fov},
            "background": "#10141c", "ambient": ambient,
            "render": {"sampler": sampler, "samples": samples, "maxDepth": depth},
            "lights": lights, "objects": objects}
def save(name, value):
    with open(os.path.join(D, name), 'w') as f:
        json.dump(value, f, indent=1)
floor = {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": {"type": "chalk", "color": "#b8b0a0"}}
def boxes(n, spread):
    out = []
    for _ in range(n):
        s = [R.uniform(0.2, 0.7), R.uniform(0.2, 1.2), R.uniform(0.2, 0.7)]
        out.append({"type": "box", "center": [R.uniform(-spread, spread), s[1] / 2, R.uniform(-spread, spread * 0.6)],
                    "size": s, "rotation": [0, R.uniform(0, 90), 0], "material": mat()})
    return out
# 1. a glass ball and a glass box over 90 boxes
o = [floor] + boxes(90, 4.5) + [
    {"type": "sphere", "center": [0.3, 1.9, 0.6], "radius": 0.9, "material": {"type": "glass", "ior": 1.5}},
    {"type": "box", "center": [-1.6, 1.6, 1.4], "size": [0.8, 0.8, 0.8], "rotation": [20, 35, 10], "material": {"type": "glass", "ior": 1.45, "color": "#d8ecff"}}]
save('glass-crowd.json', scene("glass-crowd", 800, 600, [0.5, 4.0, 7.5], [0, 0.8, 0], 48,
    [{"type": "point", "position": [3, 8, 5], "color": "#ffffff", "intensity": 0.9},
     {"type": "point", "position": [-6, 5, 2], "color": "#a0b8ff", "intensity": 0.3}], o))
# 2. a corridor of mirrors with metal and glass spheres
o = [floor,
     {"type": "plane", "point": [-2.2, 0, 0], "normal": [1, 0, 0], "material": {"type": "mirror", "color": "#e0f0ff", "reflectivity": 0.85}},
     {"type": "plane", "point": [2.2, 0, 0], "normal": [-1, 0, 0], "material": {"type": "mirror", "color": "#fff0e0", "reflectivity": 0.85}},
     {"type": "plane", "point": [0, 3.2, 0], "normal": [0, -1, 0], "material": {"type": "chalk", "color": "#e8e8e8"}}]
for i in range(9):
    z = -i * 1.3
    o.append({"type": "sphere", "center": [R.uniform(-1.2, 1.2), 0.35, z], "radius": 0.35,
              "material": R.choice([{"type": "metal", "color": col()}, {"type": "glass", "ior": 1.5}, {"type": "plastic", "color": col()}])})
save('mirror-corridor.json', scene("mirror-corridor", 800, 600, [0.4, 1.5, 3.5], [0, 0.8, -4], 55,
    [{"type": "point", "position": [0, 3.0, 1.0], "color": "#fff4e0", "intensity": 1.0},
     {"type": "point", "position": [0.5, 2.5, -7], "color": "#e0e8ff", "intensity": 0.6}], o, depth=12))
# 3. a cloud of 7,000 small spheres over a floor
o = [floor]
for _ in range(7000):
    r = R.uniform(0.03, 0.08)
    o.append({"type": "sphere", "center": [R.uniform(-3, 3), R.uniform(0.1, 3.0), R.uniform(-3, 1.5)], "radius": r, "material": mat()})
save('sphere-cloud.json', scene("sphere-cloud", 800, 600, [0, 1.8, 6.0], [0, 1.4, 0], 50,
    [{"type": "point", "position": [4, 6, 6], "color": "#ffffff", "intensity": 1.0}], o))
# 4. a terrain mesh (OBJ, 160x160 quads = 51,200 triangles) with a glass ball and a metal ball
N = 160
with open(os.path.join(D, 'terrain.obj'), 'w') as f:
    for j in range(N + 1):
        for i in range(N + 1):
            x, z = i / N * 8 - 4, j / N * 8 - 4
            y = 0.35 * math.sin(1.3 * x + 0.4 * z) + 0.25 * math.cos(0.9 * z - 0.7 * x) + 0.08 * math.sin(5.1 * x) * math.cos(4.3 * z)
            f.write('v %.5f %.5f %.5f\n' % (x, y, z))
    for j in range(N):
        for i in range(N):
            a = j * (N + 1) + i + 1
            f.write('f %d %d %d\nf %d %d %d\n' % (a, a + N + 1, a + 1, a + 1, a + N + 1, a + N + 2))
o = [{"type": "mesh", "file": "terrain.obj", "position": [0, 0, 0], "scale": 1.0, "material": {"type": "chalk", "color": "#c8a878"}},
     {"type": "sphere", "center": [-0.8, 1.2, 0.5], "radius": 0.5, "material": {"type": "glass", "ior": 1.5}},
     {"type": "sphere", "center": [1.2, 1.0, -0.8], "radius": 0.45, "material": {"type": "metal", "color": "#d0d0e0"}}]
save('terrain.json', scene("terrain", 800, 600, [0, 3.0, 6.0], [0, 0.2, 0], 50,
    [{"type": "point", "position": [-5, 7, 4], "color": "#fff0d8", "intensity": 1.0}], o))
# soft: 40 boxes under a sphere light; a table (boxes) under an area light with a glass ball
o = [floor] + boxes(40, 3.0)
save('soft/soft-blocks.json', scene("soft-blocks", 320, 240, [0, 3.5, 6.5], [0, 0.4, 0], 45,
    [{"type": "point", "position": [1.0, 4.0, 1.5], "radius": 0.6, "color": "#ffffff", "intensity": 1.0}], o, depth=6, ambient=0.05))
o = [floor, {"type": "plane", "point": [0, 0, -3], "normal": [0, 0, 1], "material": {"type": "chalk", "color": "#d8d0c0"}},
     {"type": "box", "center": [0, 0.9, 0], "size": [2.2, 0.08, 1.2], "material": {"type": "plastic", "color": "#8a5a30"}}]
for x in (-1.0, 1.0):
    for z in (-0.5, 0.5):
        o.append({"type": "box", "center": [x, 0.43, z], "size": [0.08, 0.86, 0.08], "material": {"type": "chalk", "color": "#5a3a20"}})
o += [{"type": "sphere", "center": [0.4, 1.24, 0.1], "radius": 0.3, "material": {"type": "glass", "ior": 1.5}},
      {"type": "box", "center": [-0.5, 1.09, -0.1], "size": [0.3, 0.3, 0.3], "rotation": [0, 30, 0], "material": {"type": "plastic", "color": "#3070c0"}}]
save('soft/soft-table.json', scene("soft-table", 320, 240, [0.5, 2.2, 4.5], [0, 0.7, 0], 45,
    [{"type": "area", "position": [0.3, 2.8, 0.6], "size": [1.2, 0.9], "lookAt": [0, 0, 0], "color": "#fff4e0", "intensity": 1.0}], o, depth=6, ambient=0.04))
# cluster job: 960x720, 36 jittered samples, a glass ball and a mirror over 45 boxes
o = [floor] + boxes(45, 3.5) + [
    {"type": "sphere", "center": [-0.4, 1.6, 0.4], "radius": 0.8, "material": {"type": "glass", "ior": 1.5}},
    {"type": "box", "center": [1.8, 1.2, -1.5], "size": [1.4, 2.4, 0.1], "rotation": [0, -25, 0], "material": {"type": "mirror"}}]
save('cluster-job.json', scene("cluster-job", 960, 720, [0.8, 3.2, 7.0], [0, 0.8, 0], 48,
    [{"type": "point", "position": [3, 7, 5], "color": "#ffffff", "intensity": 0.9}], o, samples=36))
# soft, written later (before the umbra test and the halves' growing limit were tuned): a city of boxes
# under a large sphere light; a shelf before a wall under a long strip light
C = random.Random(6060)
def box(lo, hi, material):
    return {"type": "box", "center": [round((a + b) / 2, 4) for a, b in zip(lo, hi)],
            "size": [round(b - a, 4) for a, b in zip(lo, hi)], "material": material}
o = [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": {"type": "chalk", "color": "#c8c8c0"}}]
for i in range(-3, 4):
    for j in range(-3, 3):
        if C.random() < 0.35: continue
        h = 0.2 + C.random() * 1.1
        cx, cz = i * 0.55 + C.uniform(-0.08, 0.08), j * 0.55 + C.uniform(-0.08, 0.08)
        o.append(box([cx - 0.18, 0, cz - 0.18], [cx + 0.18, h, cz + 0.18],
                     {"type": C.choice(["chalk", "plastic"]), "color": C.choice(["#d9d2c5", "#8fa3b8", "#c98e6b", "#9bb08a"])}))
o.append({"type": "sphere", "center": [0.25, 0.3, 1.2], "radius": 0.3, "material": {"type": "mirror", "color": "#e8e8e8"}})
city = scene("soft-city", 320, 240, [3.2, 3.0, 4.4], [0, 0.3, 0], 42,
    [{"type": "point", "position": [-1.5, 3.5, 1.0], "radius": 0.6, "color": "#fff2dd", "intensity": 1.1}], o, depth=5, ambient=0.03)
city["background"] = "#0c1018"
save('soft/soft-city.json', city)
wood = {"type": "plastic", "color": "#6b4f3a"}
o = [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": {"type": "chalk", "color": "#b9b4aa"}},
     {"type": "plane", "point": [0, 0, -1.6], "normal": [0, 0, 1], "material": {"type": "chalk", "color": "#a9aeb6"}},
     box([-1.4, 0.0, -0.5], [-1.25, 0.9, -0.2], wood), box([1.25, 0.0, -0.5], [1.4, 0.9, -0.2], wood),
     box([-1.5, 0.9, -0.6], [1.5, 0.98, -0.1], {"type": "plastic", "color": "#8a6a50"}),
     box([-0.9, 0.98, -0.45], [-0.5, 1.38, -0.2], {"type": "glass", "color": "#ffffff"}),
     {"type": "sphere", "center": [0.1, 1.16, -0.35], "radius": 0.18, "material": {"type": "plastic", "color": "#c0392b"}},
     {"type": "sphere", "center": [0.7, 1.1, -0.3], "radius": 0.12, "material": {"type": "metal", "color": "#d4af37"}},
     {"type": "sphere", "center": [-0.2, 0.25, 0.5], "radius": 0.25, "material": {"type": "chalk", "color": "#2e86c1"}}]
shelf = scene("soft-shelf", 320, 240, [0.6, 1.7, 3.6], [0, 0.6, -0.3], 48,
    [{"type": "area", "position": [0.8, 2.6, 0.9], "size": [2.0, 0.35], "lookAt": [0, 0.4, -0.4], "color": "#ffffff", "intensity": 1.2}],
    o, depth=6, ambient=0.05)
shelf["background"] = "#0e0e12"
save('soft/soft-shelf.json', shelf)
