#!/usr/bin/env python3
"""Independent mesh evidence for one link of a labelled robot file (no massprops involved).

usage: tools/labelled_mesh_evidence.py setN/FILE LINK [LINK ...]
       (MASSPROPS_SNAPSHOTS: the folder of tools/labelled_snapshots.py, default ../snapshots beside
       the checkout; the labelled files are read from ../shared/labelled)

Written to judge, without massprops, the warnings that `massprops check` gives on ../shared/labelled
when the robots' meshes are present (testdata/labels/labelled-meshes-judged.tsv, docs/labels.md).

For each link: mass, COM, inertia (rotated into the link frame), principal moments, k = sqrt(tr(I)/(2m));
for each collision/visual mesh: the vertex bounding box in the LINK frame (mesh scale + geometry
origin applied; DAE node matrices and <unit meter> applied), the COM's position relative to that box,
the solid-box inertia of that box for the link's mass, and the bound m*(half-diagonal)^2 on
integral |x-o|^2 dm. Also the link's joints and its welded (fixed-joint) neighbours with their masses.
Pure python3 (no numpy): STL (binary/ascii), OBJ, DAE.
"""
import math, os, re, struct, sys, glob
import xml.etree.ElementTree as ET

_ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..')
LAB = os.path.join(_ROOT, '..', 'shared', 'labelled')
SNAP = os.environ.get('MASSPROPS_SNAPSHOTS', os.path.join(_ROOT, '..', 'snapshots'))

# ---------- small linear algebra ----------
def rpy_matrix(r, p, y):
    cr, sr, cp, sp, cy, sy = math.cos(r), math.sin(r), math.cos(p), math.sin(p), math.cos(y), math.sin(y)
    return [[cy*cp, cy*sp*sr - sy*cr, cy*sp*cr + sy*sr],
            [sy*cp, sy*sp*sr + cy*cr, sy*sp*cr - cy*sr],
            [-sp, cp*sr, cp*cr]]

def mm(A, B):
    return [[sum(A[i][k]*B[k][j] for k in range(len(B))) for j in range(len(B[0]))] for i in range(len(A))]

def tr(A):
    return [list(r) for r in zip(*A)]

def mv(A, v):
    return [sum(A[i][k]*v[k] for k in range(3)) for i in range(3)]

def eig_sym3(A):
    # Jacobi rotations on a 3x3 symmetric matrix
    a = [row[:] for row in A]
    for _ in range(60):
        off = max(abs(a[0][1]), abs(a[0][2]), abs(a[1][2]))
        if off < 1e-300:
            break
        for p, q in ((0, 1), (0, 2), (1, 2)):
            if abs(a[p][q]) < 1e-300:
                continue
            th = (a[q][q] - a[p][p]) / (2*a[p][q])
            t = (1 if th >= 0 else -1) / (abs(th) + math.sqrt(th*th + 1))
            c = 1/math.sqrt(t*t + 1); s = t*c
            J = [[1 if i == j else 0 for j in range(3)] for i in range(3)]
            J[p][p] = c; J[q][q] = c; J[p][q] = s; J[q][p] = -s
            a = mm(tr(J), mm(a, J))
    return sorted(a[i][i] for i in range(3))

# ---------- mesh readers ----------
def read_stl(path):
    data = open(path, 'rb').read()
    if len(data) >= 84:
        n = struct.unpack('<I', data[80:84])[0]
        if 84 + 50*n == len(data):
            pts = []
            for i in range(n):
                off = 84 + 50*i + 12
                v = struct.unpack('<9f', data[off:off+36])
                pts += [v[0:3], v[3:6], v[6:9]]
            return pts, {}
    txt = data.decode('latin1')
    pts = [tuple(float(x) for x in m.groups()) for m in
           re.finditer(r'vertex\s+(\S+)\s+(\S+)\s+(\S+)', txt)]
    return pts, {}

def read_obj(path):
    pts = []
    for line in open(path, errors='replace'):
        if line.startswith('v '):
            f = line.split()
            pts.append((float(f[1]), float(f[2]), float(f[3])))
    return pts, {}

def read_dae(path):
    root = ET.parse(path).getroot()
    ns = root.tag[:root.tag.index('}')+1] if root.tag.startswith('{') else ''
    info = {}
    unit = root.find(f'{ns}asset/{ns}unit')
    meter = float(unit.get('meter', '1')) if unit is not None else 1.0
    up = root.find(f'{ns}asset/{ns}up_axis')
    info['unit_meter'] = meter
    info['up_axis'] = up.text.strip() if up is not None and up.text else 'Y_UP(default)'
    geoms = {}
    for g in root.iter(f'{ns}geometry'):
        m = g.find(f'{ns}mesh')
        if m is None:
            continue
        verts = m.find(f'{ns}vertices')
        src_id = None
        if verts is not None:
            for inp in verts.findall(f'{ns}input'):
                if inp.get('semantic') == 'POSITION':
                    src_id = inp.get('source', '')[1:]
        pts = []
        for s in m.findall(f'{ns}source'):
            if src_id and s.get('id') != src_id:
                continue
            fa = s.find(f'{ns}float_array')
            if fa is None or not fa.text:
                continue
            vals = [float(x) for x in fa.text.split()]
            pts = [tuple(vals[i:i+3]) for i in range(0, len(vals) - 2, 3)]
            break
        geoms[g.get('id')] = pts

    def node_mat(node):
        M = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]
        for ch in node:
            tag = ch.tag[len(ns):]
            if tag == 'matrix':
                v = [float(x) for x in ch.text.split()]
                M = mm(M, [v[0:4], v[4:8], v[8:12], v[12:16]])
            elif tag == 'translate':
                v = [float(x) for x in ch.text.split()]
                M = mm(M, [[1, 0, 0, v[0]], [0, 1, 0, v[1]], [0, 0, 1, v[2]], [0, 0, 0, 1]])
            elif tag == 'scale':
                v = [float(x) for x in ch.text.split()]
                M = mm(M, [[v[0], 0, 0, 0], [0, v[1], 0, 0], [0, 0, v[2], 0], [0, 0, 0, 1]])
            elif tag == 'rotate':
                v = [float(x) for x in ch.text.split()]
                ax = v[:3]; n = math.sqrt(sum(a*a for a in ax)) or 1; x, y, z = (a/n for a in ax)
                a = math.radians(v[3]); c, s = math.cos(a), math.sin(a); C = 1 - c
                R = [[c+x*x*C, x*y*C-z*s, x*z*C+y*s, 0], [y*x*C+z*s, c+y*y*C, y*z*C-x*s, 0],
                     [z*x*C-y*s, z*y*C+x*s, c+z*z*C, 0], [0, 0, 0, 1]]
                M = mm(M, R)
        return M

    out = []
    scenes = list(root.iter(f'{ns}visual_scene'))
    used = False

    def walk(node, M):
        nonlocal used
        M2 = mm(M, node_mat(node))
        for ig in node.findall(f'{ns}instance_geometry'):
            gid = ig.get('url', '')[1:]
            for p in geoms.get(gid, []):
                q = [sum(M2[i][k]*p[k] for k in range(3)) + M2[i][3] for i in range(3)]
                out.append(tuple(q))
            used = True
        for ch in node.findall(f'{ns}node'):
            walk(ch, M2)

    I4 = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]
    for sc in scenes[:1]:
        for n in sc.findall(f'{ns}node'):
            walk(n, I4)
    if not used:
        for pts in geoms.values():
            out += pts
        info['note'] = 'no visual_scene: raw positions'
    out = [(x*meter, y*meter, z*meter) for x, y, z in out]
    if os.environ.get('YUP') == '1' and info['up_axis'].startswith('Y_UP'):
        # what assimp does by default: rotate a Y_UP scene +90 deg about X so that Y becomes Z
        out = [(x, -z, y) for x, y, z in out]
        info['yup_converted'] = True
    return out, info

def read_mesh(path):
    ext = path.lower().rsplit('.', 1)[-1]
    if ext == 'stl':
        return read_stl(path)
    if ext == 'obj':
        return read_obj(path)
    if ext == 'dae':
        return read_dae(path)
    raise ValueError('unknown mesh type ' + ext)

# ---------- file / repository resolution ----------
def manifest(setname):
    rows = {}
    lines = open(f'{LAB}/{setname}/manifest.tsv').read().splitlines()
    hdr = lines[0].split('\t')
    for l in lines[1:]:
        f = dict(zip(hdr, l.split('\t')))
        rows[f['file']] = f
    return rows

def snapshot_root(repo, commit):
    d = f"{SNAP}/{repo.replace('/', '+')}/{commit}"
    if os.path.isdir(d):
        return d
    # sources.tsv may map a manifest commit onto another written commit
    for l in open(f'{SNAP}/sources.tsv').read().splitlines()[1:]:
        f = l.split('\t')
        if f[0] == repo and f[1] == commit and f[2] != 'none':
            return f"{SNAP}/{repo.replace('/', '+')}/{f[2]}"
    return d

_pkg_cache = {}
RESOLVE_NOTES = []
def find_package(root, name):
    key = (root, name)
    if key in _pkg_cache:
        return _pkg_cache[key]
    cands = []
    for dp, dn, fn in os.walk(root):
        if 'package.xml' in fn:
            try:
                t = ET.parse(os.path.join(dp, 'package.xml')).getroot().findtext('name')
            except Exception:
                t = None
            if t and t.strip() == name:
                cands.append(dp)
        if os.path.basename(dp) == name:
            cands.append(dp)
    _pkg_cache[key] = cands
    return cands

def resolve(fname, root, filedir, setname):
    if fname.startswith('package://'):
        rest = fname[len('package://'):]
        pkg, sub = rest.split('/', 1)
        for c in find_package(root, pkg):
            p = os.path.join(c, sub)
            if os.path.exists(p):
                return p
        # fallback (e.g. icub-models installs iCub_creo2urdf/meshes_creo2urdf as package iCub):
        # a file whose path ends with SUB, preferring the one under the labelled file's top folder
        hits = [os.path.join(dp, f) for dp, dn, fn in os.walk(root) for f in fn
                if os.path.join(dp, f).endswith('/' + sub)]
        top = os.path.relpath(filedir, root).split('/')[0]
        hits.sort(key=lambda h: (not os.path.relpath(h, root).startswith(top + '/'), len(h)))
        if hits:
            RESOLVE_NOTES.append(f'package://{pkg} resolved by suffix to {os.path.relpath(hits[0], root)}'
                                 + (f' ({len(hits)} candidates)' if len(hits) > 1 else ''))
            return hits[0]
        return None
    if fname.startswith('model://'):
        rest = fname[len('model://'):]
        for base in (f'{LAB}/{setname}/modelpath', f'{root}/models', os.path.dirname(filedir)):
            p = os.path.join(base, rest)
            if os.path.exists(p):
                return p
        return None
    if fname.startswith('file://'):
        fname = fname[7:]
    p = os.path.normpath(os.path.join(filedir, fname))
    if os.path.exists(p):
        return p
    # case-insensitive fallback
    d, b = os.path.split(p)
    if os.path.isdir(d):
        for f in os.listdir(d):
            if f.lower() == b.lower():
                return os.path.join(d, f)
    return None

def fl(s, n=3, default=0.0):
    if s is None:
        return [default]*n
    v = [float(x) for x in s.split()]
    return v

# ---------- URDF / SDF ----------
def urdf_links(path):
    root = ET.parse(path).getroot()
    links = {}
    for L in root.findall('link'):
        d = {'name': L.get('name'), 'mass': None, 'geoms': []}
        ine = L.find('inertial')
        if ine is not None:
            o = ine.find('origin')
            d['com'] = fl(o.get('xyz') if o is not None else None)
            d['irpy'] = fl(o.get('rpy') if o is not None else None)
            m = ine.find('mass')
            d['mass'] = float(m.get('value')) if m is not None else None
            i = ine.find('inertia')
            if i is not None:
                g = lambda k: float(i.get(k, '0'))
                d['I'] = [[g('ixx'), g('ixy'), g('ixz')], [g('ixy'), g('iyy'), g('iyz')],
                          [g('ixz'), g('iyz'), g('izz')]]
        for kind in ('collision', 'visual'):
            for G in L.findall(kind):
                o = G.find('origin')
                xyz = fl(o.get('xyz') if o is not None else None)
                rpy = fl(o.get('rpy') if o is not None else None)
                geo = G.find('geometry')
                if geo is None or len(geo) == 0:
                    continue
                sh = geo[0]
                d['geoms'].append({'kind': kind, 'xyz': xyz, 'rpy': rpy, 'shape': sh.tag,
                                   'attrs': dict(sh.attrib)})
        links[d['name']] = d
    joints = []
    for J in root.findall('joint'):
        o = J.find('origin')
        joints.append({'name': J.get('name'), 'type': J.get('type'),
                       'parent': J.find('parent').get('link'), 'child': J.find('child').get('link'),
                       'xyz': fl(o.get('xyz') if o is not None else None)})
    return links, joints

def sdf_pose(el):
    p = el.find('pose') if el is not None else None
    if p is None or not p.text:
        return [0, 0, 0], [0, 0, 0]
    v = [float(x) for x in p.text.split()]
    return v[:3], v[3:6]

def sdf_links(path):
    root = ET.parse(path).getroot()
    model = root.find('model')
    links = {}
    for L in model.findall('link'):
        d = {'name': L.get('name'), 'mass': None, 'geoms': []}
        lxyz, lrpy = sdf_pose(L)
        d['link_pose'] = (lxyz, lrpy)
        ine = L.find('inertial')
        if ine is not None:
            xyz, rpy = sdf_pose(ine)
            d['com'] = xyz; d['irpy'] = rpy
            d['mass'] = float(ine.findtext('mass', '0'))
            i = ine.find('inertia')
            if i is not None:
                g = lambda k: float(i.findtext(k, '0'))
                d['I'] = [[g('ixx'), g('ixy'), g('ixz')], [g('ixy'), g('iyy'), g('iyz')],
                          [g('ixz'), g('iyz'), g('izz')]]
        for kind in ('collision', 'visual'):
            for G in L.findall(kind):
                xyz, rpy = sdf_pose(G)
                geo = G.find('geometry')
                if geo is None or len(geo) == 0:
                    continue
                sh = geo[0]
                attrs = {}
                if sh.tag == 'mesh':
                    attrs['filename'] = sh.findtext('uri', '').strip()
                    if sh.find('scale') is not None:
                        attrs['scale'] = sh.findtext('scale')
                elif sh.tag == 'box':
                    attrs['size'] = sh.findtext('size')
                elif sh.tag in ('cylinder', 'sphere'):
                    attrs['radius'] = sh.findtext('radius')
                    if sh.find('length') is not None:
                        attrs['length'] = sh.findtext('length')
                d['geoms'].append({'kind': kind, 'xyz': xyz, 'rpy': rpy, 'shape': sh.tag, 'attrs': attrs})
        links[d['name']] = d
    joints = []
    for J in model.findall('joint'):
        joints.append({'name': J.get('name'), 'type': J.get('type'), 'parent': J.findtext('parent'),
                       'child': J.findtext('child'), 'xyz': sdf_pose(J)[0]})
    return links, joints

def primitive_points(g):
    a = g['attrs']
    if g['shape'] == 'box':
        sx, sy, sz = fl(a['size'])
        return [(x*sx/2, y*sy/2, z*sz/2) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
    if g['shape'] == 'cylinder':
        r = float(a['radius']); h = float(a['length'])
        return [(x*r, y*r, z*h/2) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
    if g['shape'] == 'sphere':
        r = float(a['radius'])
        return [(x*r, y*r, z*r) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
    return []

def fmt(v, p=4):
    return '(' + ', '.join(f'{x:.{p}g}' for x in v) + ')'

def main():
    spec = sys.argv[1]
    setname, fname = spec.split('/', 1)
    man = manifest(setname)[fname]
    root = snapshot_root(man['repo'], man['commit'])
    filedir = os.path.dirname(os.path.join(root, man['path']))
    path = f'{LAB}/{setname}/files/{fname}'
    links, joints = (sdf_links if fname.endswith('.sdf') else urdf_links)(path)
    for ln in sys.argv[2:]:
        L = links.get(ln)
        print(f'=== {spec} link {ln}')
        if L is None:
            print('  (no such link)'); continue
        m = L['mass']
        if L.get('I') is not None and m:
            R = rpy_matrix(*L['irpy'])
            Il = mm(R, mm(L['I'], tr(R)))
            lam = eig_sym3(Il)
            t = sum(lam)
            k = math.sqrt(t/(2*m)) if m > 0 else float('nan')
            print(f"  mass {m:.6g} kg  com {fmt(L['com'])}  diag {fmt([Il[0][0], Il[1][1], Il[2][2]])}"
                  f"  prod {fmt([Il[0][1], Il[0][2], Il[1][2]])}")
            print(f'  principal {fmt(lam)}  k=sqrt(trI/2m) {k:.4g} m')
        else:
            print(f'  mass {m} (no inertia)')
        # joints
        for j in joints:
            if j['child'] == ln:
                pm = links.get(j['parent'], {}).get('mass')
                print(f"  parent joint {j['name']} ({j['type']}) from {j['parent']} (m {pm}) at {fmt(j['xyz'])}")
        for j in joints:
            if j['parent'] == ln:
                cm = links.get(j['child'], {}).get('mass')
                print(f"  child joint {j['name']} ({j['type']}) to {j['child']} (m {cm}) at {fmt(j['xyz'])}")
        printed = set()
        union = {}
        allpts = {}
        for g in L['geoms']:
            a = g['attrs']
            if g['shape'] == 'mesh':
                mp = resolve(a.get('filename', ''), root, filedir, setname)
                if not mp:
                    print(f"  {g['kind']} mesh {a.get('filename')} NOT FOUND"); continue
                try:
                    pts, info = read_mesh(mp)
                except Exception as e:
                    print(f"  {g['kind']} mesh {mp}: read error {e}"); continue
                sc = fl(a.get('scale'), 3, 1.0) if a.get('scale') else [1.0, 1.0, 1.0]
                desc = f"{g['kind']} mesh {os.path.relpath(mp, root)} scale {fmt(sc)} {info}"
            else:
                pts = primitive_points(g); sc = [1, 1, 1]
                desc = f"{g['kind']} {g['shape']} {a}"
            if not pts:
                print(f'  {desc}: no vertices'); continue
            R = rpy_matrix(*g['rpy'])
            q = [mv(R, [p[0]*sc[0], p[1]*sc[1], p[2]*sc[2]]) for p in pts]
            q = [[v[i] + g['xyz'][i] for i in range(3)] for v in q]
            lo = [min(v[i] for v in q) for i in range(3)]
            hi = [max(v[i] for v in q) for i in range(3)]
            size = [hi[i] - lo[i] for i in range(3)]
            ctr = [(hi[i] + lo[i])/2 for i in range(3)]
            hd = math.sqrt(sum(s*s for s in size))/2
            allpts.setdefault(g['kind'], []).extend(q)
            u = union.setdefault(g['kind'], [lo[:], hi[:]])
            u[0] = [min(u[0][i], lo[i]) for i in range(3)]; u[1] = [max(u[1][i], hi[i]) for i in range(3)]
            key = tuple(round(x, 7) for x in lo + hi)
            if key in printed:
                print(f"  {g['kind']} {g['shape']}: same box as above"); continue
            printed.add(key)
            print(f'  {desc}  ({len(pts)} verts) origin {fmt(g["xyz"])} rpy {fmt(g["rpy"])}')
            print(f'    box in link frame {fmt(lo)} to {fmt(hi)}  size {fmt([s*1000 for s in size])} mm'
                  f'  half-diag {hd:.4g} m')
            if L.get('I') is not None and m:
                c = L['com']
                out = [max(lo[i] - c[i], 0, c[i] - hi[i]) for i in range(3)]
                dout = math.sqrt(sum(o*o for o in out))
                rel = [(c[i] - ctr[i]) for i in range(3)]
                print(f'    com - box center {fmt(rel)} ; com outside box by {dout*1000:.3g} mm')
                a2, b2, c2 = (s*s for s in size)
                Ibox = [m*(b2 + c2)/12, m*(a2 + c2)/12, m*(a2 + b2)/12]
                kbox = math.sqrt((a2 + b2 + c2)/12)
                oc = sum(r*r for r in rel)
                need = t/2 + m*oc
                cap = m*hd*hd
                print(f'    solid box of m: I {fmt(Ibox)} k_box {kbox:.4g} m ; k/k_box {k/kbox if kbox else float("inf"):.3g}'
                      f' ; int|x-o|^2 = trI/2+m|c-o|^2 = {need:.4g} vs m*hd^2 {cap:.4g} (ratio {need/cap if cap else float("inf"):.3g})')
        kind = 'collision' if 'collision' in union else ('visual' if 'visual' in union else None)
        if kind and L.get('I') is not None and m:
            lo, hi = union[kind]
            size = [hi[i] - lo[i] for i in range(3)]; ctr = [(hi[i] + lo[i])/2 for i in range(3)]
            hd = math.sqrt(sum(x*x for x in size))/2
            c = L['com']
            dout = math.sqrt(sum(max(lo[i] - c[i], 0, c[i] - hi[i])**2 for i in range(3)))
            kbox = math.sqrt(sum(x*x for x in size)/12)
            need = t/2 + m*sum((c[i]-ctr[i])**2 for i in range(3))
            # per-axis bound: about a link-frame axis through the COM, I_aa <= m * max distance^2 of
            # the mesh's vertices from that axis (all mass on the farthest point)
            axr = []
            for a_ in range(3):
                b_, c_ = [i for i in range(3) if i != a_]
                r2 = max((v[b_]-c[b_])**2 + (v[c_]-c[c_])**2 for v in allpts[kind])
                axr.append(Il[a_][a_]/(m*r2) if r2 > 0 else float('inf'))
            print(f"  per-axis: I_aa / (m * max vertex distance^2 from the axis through the COM) = {fmt(axr, 3)}")
            print(f"BRIEF\t{spec}\t{ln}\t{kind}\tm={m:.4g}\tsize_mm={'x'.join(f'{x*1000:.0f}' for x in size)}"
                  f"\tk={k:.3g}\tk_box={kbox:.3g}\tk/k_box={k/kbox if kbox else float('inf'):.3g}"
                  f"\tneed/cap={need/(m*hd*hd) if hd else float('inf'):.3g}\tcom_out_mm={dout*1000:.3g}\taxis_ratio={max(axr):.3g}"
                  f"\tdiag={fmt([Il[0][0], Il[1][1], Il[2][2]], 3)}\tcom={fmt(c, 3)}")
        for n in RESOLVE_NOTES:
            print('  note:', n)
        RESOLVE_NOTES.clear()
        # welded neighbours
        fixed = [j for j in joints if j['type'] == 'fixed' and ln in (j['parent'], j['child'])]
        for j in fixed:
            other = j['child'] if j['parent'] == ln else j['parent']
            print(f"  welded to {other} (m {links.get(other, {}).get('mass')}) via {j['name']}")

if __name__ == '__main__':
    main()
