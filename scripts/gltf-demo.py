#!/usr/bin/env python3
"""Writes a glTF 2.0 model from scratch, and a scene that places it, into a folder (default: here).

The model: a node moved by (2, 0, 0) and scaled by 2, whose child turns 90 degrees about y and
whose grandchild lifts a unit cube by 0.25; the cube's base colour texture is red on its left half
(u < 0.5) and blue on its right. Beside it, a node at (-2, 1, 0) holds a gold metal ball (metallic 1,
roughness 0.2). All buffers and the PNG are embedded (data: URI). Render it:

    python3 scripts/gltf-demo.py /tmp/gltf-demo
    bin/studio render /tmp/gltf-demo/scene.json -o docs/gltf.jpg
"""
import json, struct, base64, math, zlib
def png(w,h,pix):
    raw=b''.join(b'\x00'+bytes(sum((pix(x,y) for x in range(w)),())) for y in range(h))
    def chunk(t,d): return struct.pack('>I',len(d))+t+d+struct.pack('>I',zlib.crc32(t+d)&0xffffffff)
    return b'\x89PNG\r\n\x1a\n'+chunk(b'IHDR',struct.pack('>IIBBBBB',w,h,8,2,0,0,0))+chunk(b'IDAT',zlib.compress(raw))+chunk(b'IEND',b'')
# texture: left half red, right half blue (u<0.5 red)
img=png(16,16,lambda x,y:(220,30,30) if x<8 else (30,30,220))
# cube: 24 vertices, uv per face
P=[];N=[];U=[];I=[]
faces=[((1,0,0),(0,0,-1),(0,1,0)),((-1,0,0),(0,0,1),(0,1,0)),((0,1,0),(1,0,0),(0,0,-1)),((0,-1,0),(1,0,0),(0,0,1)),((0,0,1),(1,0,0),(0,1,0)),((0,0,-1),(-1,0,0),(0,1,0))]
for n,u,v in faces:
    b=len(P)
    for (su,sv) in [(-1,-1),(1,-1),(1,1),(-1,1)]:
        P.append([0.5*(n[i]+su*u[i]+sv*v[i]) for i in range(3)]); N.append(list(n)); U.append([(su+1)/2,(1-sv)/2])
    I+= [b,b+1,b+2,b,b+2,b+3]
# sphere
SP=[];SN=[];SI=[]
st,sl=16,24
for i in range(st+1):
    th=math.pi*i/st
    for j in range(sl+1):
        ph=2*math.pi*j/sl
        p=[math.sin(th)*math.cos(ph),math.cos(th),math.sin(th)*math.sin(ph)]
        SP.append([0.5*c for c in p]); SN.append(p)
for i in range(st):
    for j in range(sl):
        a=i*(sl+1)+j; b=a+sl+1
        SI+=[a,a+1,b,a+1,b+1,b]
def f32(a): return b''.join(struct.pack('<%df'%len(x),*x) for x in a)
def u16(a): return struct.pack('<%dH'%len(a),*a)
parts=[f32(P),f32(N),f32(U),u16(I),f32(SP),f32(SN),u16(SI),img]
views=[];buf=b''
for p in parts:
    while len(buf)%4: buf+=b'\x00'
    views.append({"buffer":0,"byteOffset":len(buf),"byteLength":len(p)}); buf+=p
def mm(a): return [min(x[i] for x in a) for i in range(3)],[max(x[i] for x in a) for i in range(3)]
acc=[
 {"bufferView":0,"componentType":5126,"count":len(P),"type":"VEC3","min":mm(P)[0],"max":mm(P)[1]},
 {"bufferView":1,"componentType":5126,"count":len(N),"type":"VEC3"},
 {"bufferView":2,"componentType":5126,"count":len(U),"type":"VEC2"},
 {"bufferView":3,"componentType":5123,"count":len(I),"type":"SCALAR"},
 {"bufferView":4,"componentType":5126,"count":len(SP),"type":"VEC3","min":mm(SP)[0],"max":mm(SP)[1]},
 {"bufferView":5,"componentType":5126,"count":len(SN),"type":"VEC3"},
 {"bufferView":6,"componentType":5123,"count":len(SI),"type":"SCALAR"}]
s2=math.sqrt(0.5)
g={"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0,3]}],
 "nodes":[{"translation":[2,0,0],"scale":[2,2,2],"children":[1]},
          {"rotation":[0,s2,0,s2],"children":[2]},
          {"translation":[0,0.25,0],"mesh":0},
          {"translation":[-2,1,0],"mesh":1}],
 "meshes":[{"primitives":[{"attributes":{"POSITION":0,"NORMAL":1,"TEXCOORD_0":2},"indices":3,"material":0}]},
           {"primitives":[{"attributes":{"POSITION":4,"NORMAL":5},"indices":6,"material":1}]}],
 "materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0},"metallicFactor":0,"roughnessFactor":0.8}},
              {"pbrMetallicRoughness":{"baseColorFactor":[1.0,0.766,0.336,1],"metallicFactor":1,"roughnessFactor":0.2}}],
 "textures":[{"source":0}],"images":[{"bufferView":7,"mimeType":"image/png"}],
 "accessors":acc,"bufferViews":views,
 "buffers":[{"byteLength":len(buf),"uri":"data:application/octet-stream;base64,"+base64.b64encode(buf).decode()}]}
import os, sys
out=sys.argv[1] if len(sys.argv)>1 else '.'
os.makedirs(out, exist_ok=True)
open(os.path.join(out,'model.gltf'),'w').write(json.dumps(g))
scene={"name":"gltf-demo","image":{"width":480,"height":270,"format":"jpg"},
 "camera":{"position":[0,2,9],"lookAt":[0,1,0],"fov":50},"background":"#000000","ambient":0.3,
 "render":{"samples":16},
 "lights":[{"type":"point","position":[0,8,8],"intensity":1}],
 "objects":[{"type":"gltf","file":"model.gltf"},{"type":"plane","material":{"type":"chalk","color":"#404040"}}]}
json.dump(scene,open(os.path.join(out,'scene.json'),'w'))
