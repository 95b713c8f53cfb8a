# SPDX-License-Identifier: MIT
# Makes test/data/dense_ico.obj: the once-subdivided icosahedron (42 vertices) with random edge
# flips that raise the valence of a few neighbouring vertices (args: seed, largest valence, output).
# Used by test/test_sr48_census.c: several extraordinary vertices within two rings of each
# other, as in decimated scans.
import sys, itertools, subprocess, random
# icosahedron
t=(1+5**0.5)/2
V=[(-1,t,0),(1,t,0),(-1,-t,0),(1,-t,0),(0,-1,t),(0,1,t),(0,-1,-t),(0,1,-t),(t,0,-1),(t,0,1),(-t,0,-1),(-t,0,1)]
F=[(0,11,5),(0,5,1),(0,1,7),(0,7,10),(0,10,11),(1,5,9),(5,11,4),(11,10,2),(10,7,6),(7,1,8),(3,9,4),(3,4,2),(3,2,6),(3,6,8),(3,8,9),(4,9,5),(2,4,11),(6,2,10),(8,6,7),(9,8,1)]
def sub(V,F):
    V=list(V); mid={}
    def m(a,b):
        k=(min(a,b),max(a,b))
        if k not in mid:
            p=[(V[a][i]+V[b][i])/2 for i in range(3)]; r=sum(x*x for x in p)**0.5
            V.append(tuple(x/r*1.9 for x in p)); mid[k]=len(V)-1
        return mid[k]
    G=[]
    for a,b,c in F:
        ab,bc,ca=m(a,b),m(b,c),m(c,a); G+= [(a,ab,ca),(b,bc,ab),(c,ca,bc),(ab,bc,ca)]
    return V,G
V,F=sub(V,F)
F=[list(f) for f in F]
def edges(F):
    E={}
    for fi,f in enumerate(F):
        for i in range(3):
            a,b=f[i],f[(i+1)%3]; E.setdefault((min(a,b),max(a,b)),[]).append(fi)
    return E
def val(F):
    c=[0]*len(V)
    for f in F:
        for v in f: c[v]+=1
    return c
R=set(F[0])|{F[1][0],F[1][1],F[1][2]}
random.seed(int(sys.argv[1]))
target=int(sys.argv[2])
for it in range(4000):
    E=edges(F); c=val(F)
    cand=[]
    for (a,b),fs in E.items():
        if len(fs)!=2: continue
        f0,f1=F[fs[0]],F[fs[1]]
        cc=[v for v in f0 if v not in (a,b)][0]; d=[v for v in f1 if v not in (a,b)][0]
        if (min(cc,d),max(cc,d)) in E: continue
        if c[a]<=4 or c[b]<=4: continue
        if a in R or b in R: continue
        if cc in R or d in R: cand.append((a,b,cc,d,fs))
    if not cand: break
    a,b,cc,d,fs=random.choice(cand)
    if max(c[cc],c[d])>=target: continue
    # flip: faces (a,b,cc) & (b,a,d) oriented -> (cc,d,... ) keep orientation
    f0=F[fs[0]]; i=f0.index(cc)
    # f0 = (cc, x, y) cyclic with edge x->y = a,b in some order
    x,y=f0[(i+1)%3],f0[(i+2)%3]
    F[fs[0]]=[cc,x,d]; F[fs[1]]=[d,y,cc]
c=val(F)
with open(sys.argv[3],'w') as o:
    for v in V: o.write("v %.6f %.6f %.6f\n"%v)
    for f in F: o.write("f %d %d %d\n"%(f[0]+1,f[1]+1,f[2]+1))
print(sorted(c)[-8:])
