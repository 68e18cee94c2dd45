"""STL read/write (ASCII and binary) and seeded vertex noise, Python standard library only.

A mesh is a list of triangles, each three (x, y, z) tuples in the file's unit. Normals are not
kept: the writer recomputes them from the vertex order (right-hand rule), as the readers of
gearsim (Assimp) do not trust them anyway. Not a general mesh library: no indexing, no repair.
"""
import math
import random
import struct


def is_binary_stl(data):
    """True when the bytes are a binary STL (size = 84 + 50·n); an ASCII file never matches by chance."""
    if len(data) < 84:
        return False
    (n,) = struct.unpack_from('<I', data, 80)
    return len(data) == 84 + 50 * n


def read_stl(path):
    """Triangles and the format ('stl-binary' or 'stl-ascii') of the STL file at path."""
    data = open(path, 'rb').read()
    if is_binary_stl(data):
        (n,) = struct.unpack_from('<I', data, 80)
        tris = []
        for i in range(n):
            v = struct.unpack_from('<12f', data, 84 + 50 * i)
            tris.append(((v[3], v[4], v[5]), (v[6], v[7], v[8]), (v[9], v[10], v[11])))
        return tris, 'stl-binary'
    tris, cur = [], []
    for line in data.decode('ascii').splitlines():
        w = line.split()
        if w and w[0] == 'vertex':
            cur.append((float(w[1]), float(w[2]), float(w[3])))
            if len(cur) == 3:
                tris.append(tuple(cur))
                cur = []
    return tris, 'stl-ascii'


def _normal(t):
    (ax, ay, az), (bx, by, bz), (cx, cy, cz) = t
    ux, uy, uz = bx - ax, by - ay, bz - az
    vx, vy, vz = cx - ax, cy - ay, cz - az
    n = (uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx)
    length = math.sqrt(n[0] ** 2 + n[1] ** 2 + n[2] ** 2)
    return tuple(c / length for c in n) if length > 0 else (0.0, 0.0, 0.0)


def write_stl(path, tris, fmt, name='noisy'):
    """Writes triangles as 'stl-binary' or 'stl-ascii' (coordinates to 9 significant digits)."""
    if fmt == 'stl-binary':
        out = bytearray(b'gearsim cad_corpus ' + name.encode('ascii')[:60])
        out += b' ' * (80 - len(out))
        out += struct.pack('<I', len(tris))
        for t in tris:
            out += struct.pack('<12fH', *_normal(t), *t[0], *t[1], *t[2], 0)
        open(path, 'wb').write(bytes(out))
        return
    lines = ['solid ' + name]
    for t in tris:
        lines.append('  facet normal %.9g %.9g %.9g' % _normal(t))
        lines.append('    outer loop')
        for v in t:
            lines.append('      vertex %.9g %.9g %.9g' % v)
        lines.append('    endloop')
        lines.append('  endfacet')
    lines.append('endsolid ' + name)
    open(path, 'w').write('\n'.join(lines) + '\n')


def add_noise(tris, amplitude, seed, mode):
    """Copies of the triangles with uniform noise in [−amplitude, +amplitude] on each coordinate.

    mode 'inplane': x and y only, one draw per distinct (x, y), so the top and bottom copies of an
    outline vertex move together and a prism stays a prism. mode '3d': x, y and z, one draw per
    distinct vertex (watertightness kept, prism broken). Draws are made in order of first
    appearance in the file, so the result depends only on the file and the seed.
    """
    rng = random.Random(seed)
    moved = {}

    def move(v):
        key = (v[0], v[1]) if mode == 'inplane' else v
        if key not in moved:
            d = [rng.uniform(-amplitude, amplitude) for _ in range(len(key))]
            moved[key] = d
        d = moved[key]
        return (v[0] + d[0], v[1] + d[1], v[2] + (d[2] if mode == '3d' else 0.0))

    return [tuple(move(v) for v in t) for t in tris]
