#!/usr/bin/env python3
"""How even is the 5x5 spreadsheet of Meta5D? Measures every cell (x4, x5 in 0, 0.25, .., 1) of
meta5d.hf with the frepkit command-line tool, nothing else:

  volume    the inside fraction of the common box [-10, 10]^3, in per mille: F >= 0 at the
            centres of a G^3 grid of cells (frepkit eval of the 5-D object meta5d);
  keys      of each key shape's own inside samples (Cat, Robot, NiHon, Rob_let, evaluated as the
            objects cat, robot, nihon, roblet of the same file), the percentage also inside the
            cell: how much of each key shape the cell shows;
  overlap   with each key shape, intersection over union of the inside samples (issue 29's
            measure), and the issue's goals: a cell halfway between two keys overlaps both
            within 0.15 of each other, the middle cell overlaps all four within 0.15;
  mesh      the cell meshed as the spreadsheet meshes it (frepkit mesh --axes X,Y,Z,x4,x5 at
            --mesh-grid samples per axis): triangles, connected components, and the largest
            component's share of the enclosed volume (scattered slivers: many components, a
            small largest share).

  movie     with --frames MANIFEST (a manifest.json of frepkit demo or map, whose frames entry
            lists every frame's x4 and x5): the change from each frame to the next, 1 - overlap
            of the two frames' inside samples on a --movie-grid^3 grid, and the issue's goal: no
            change above 3 times the median change (a pop instead of a flow).

  python3 measure_spreadsheet.py [--model meta5d.hf] [--object meta5d] [--frepkit FREPKIT]
                                 [--grid 64] [--mesh-grid 128] [--frames MANIFEST]
                                 [--movie-grid 32] [--json FILE] [-- FREPKIT_ARGS]

FREPKIT_ARGS (after --) go to every frepkit eval and mesh, e.g. --library or --shape for a
metamorphosis written by frepkit morph whose keys call meshes (Documentation/metamorphosis.md).

Run from anywhere; frepkit is looked for in ../../build/bin, then on PATH.
"""
import argparse
import json
import os
import pathlib
import shutil
import statistics
import struct
import subprocess
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
STEPS = [0, 0.25, 0.5, 0.75, 1]
KEYS = [('cat', 'Cat'), ('robot', 'Robot'), ('nihon', 'NiHon'), ('roblet', 'Rob_let')]
BOX = 10.0


def find_frepkit(given):
    if given:
        return given
    built = HERE.parent.parent / 'build' / 'bin' / 'frepkit'
    if built.exists():
        return str(built)
    found = shutil.which('frepkit')
    if not found:
        sys.exit('measure_spreadsheet.py: no frepkit (give --frepkit)')
    return found


def grid_points(n):
    """Centres of an n^3 grid of cells over the box, x1 fastest."""
    c = [-BOX + 2 * BOX * (i + 0.5) / n for i in range(n)]
    return [(x, y, z) for z in c for y in c for x in c]


EXTRA = []  # FREPKIT_ARGS


def evaluate(frepkit, model, obj, lines):
    run = subprocess.run([frepkit, 'eval', str(model), '-o', obj] + EXTRA,
                         input='\n'.join(lines) + '\n', capture_output=True, text=True, check=True)
    out = run.stdout.splitlines()
    if len(out) != len(lines):
        sys.exit('frepkit eval: %d results for %d points' % (len(out), len(lines)))
    inside, errors = [], 0
    for v in out:
        if v.startswith('error'):
            errors += 1
            inside.append(False)
        else:
            inside.append(float(v) >= 0)
    return inside, errors


def mesh_statistics(frepkit, model, obj, x4, x5, samples, workdir):
    """Triangles, components and the largest component's share of the volume of one cell."""
    stl = os.path.join(workdir, 'cell.stl')
    subprocess.run([frepkit, 'mesh', str(model), '-o', stl, '--axes', 'X,Y,Z,%g,%g' % (x4, x5),
                    '--object', obj,
                    '--grid', str(samples), '--no-normals', '-q'] + EXTRA, check=True)
    data = pathlib.Path(stl).read_bytes()
    count = struct.unpack_from('<I', data, 80)[0]
    index, parent, tris = {}, [], []

    def vertex(p):
        if p not in index:
            index[p] = len(parent)
            parent.append(len(parent))
        return index[p]

    def find(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    for t in range(count):
        f = struct.unpack_from('<12f', data, 84 + 50 * t)
        a, b, c = f[3:6], f[6:9], f[9:12]
        ia, ib, ic = vertex(a), vertex(b), vertex(c)
        parent[find(ib)] = find(ia)
        parent[find(ic)] = find(ia)
        tris.append((ia, a, b, c))
    volumes = {}
    for ia, a, b, c in tris:
        v = (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
             + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6
        r = find(ia)
        volumes[r] = volumes.get(r, 0.0) + v
    total = sum(volumes.values())
    largest = max(volumes.values()) / total if total > 0 else 0.0
    return count, len(volumes), largest


def table(title, rows, fmt):
    print('\n' + title)
    print('  x5 \\ x4 ' + ''.join('%9g' % s for s in STEPS))
    for x5, row in zip(STEPS, rows):
        print('  %7g ' % x5 + ''.join(fmt % v for v in row))


def goals(cells):
    """Issue 29's goals: halfway cells overlap their two keys within 0.15 of each other, the
    middle cell its four keys within 0.15. Prints each figure with PASS or MISS."""
    def cell(x4, x5):
        return next(c for c in cells if c['x4'] == x4 and c['x5'] == x5)
    print('\ngoals (issue 29):')
    for x4, x5, a, b in ((0.5, 0, 'cat', 'robot'), (0, 0.5, 'cat', 'nihon'),
                         (1, 0.5, 'robot', 'roblet'), (0.5, 1, 'nihon', 'roblet')):
        o = cell(x4, x5)['overlap']
        gap = abs(o[a] - o[b])
        print('  (%g, %g) overlaps %s %.2f and %s %.2f: difference %.2f %s'
              % (x4, x5, a, o[a], b, o[b], gap, 'PASS' if gap <= 0.15 else 'MISS (goal 0.15)'))
    o = cell(0.5, 0.5)['overlap']
    spread = max(o.values()) - min(o.values())
    print('  (0.5, 0.5) overlaps %s: spread %.2f %s'
          % (', '.join('%s %.2f' % (k, o[k]) for k, _ in KEYS), spread,
             'PASS' if spread <= 0.15 else 'MISS (goal 0.15)'))


def overlap(a, b):
    """Intersection over union of two lists of inside flags (1 when both are empty)."""
    both = sum(1 for p, q in zip(a, b) if p and q)
    either = sum(1 for p, q in zip(a, b) if p or q)
    return both / either if either else 1.0


def frame_values(manifest):
    """Every frame's (x4, x5), in order, from a manifest's frames entry."""
    entries = [f for f in json.loads(pathlib.Path(manifest).read_text())['files']
               if f.get('kind') == 'frames']
    if not entries:
        sys.exit('%s: no frames entry' % manifest)
    return [(f['values']['x4'], f['values']['x5']) for f in entries[0]['frames']]


def movie(frepkit, model, obj, manifest, n):
    """The change from frame to frame along the movie (1 - overlap of consecutive frames) and
    the issue's goal: no change above 3 times the median."""
    xyz = ['%.9g %.9g %.9g' % q for q in grid_points(n)]
    values = frame_values(manifest)
    frames = [evaluate(frepkit, model, obj, ['%s %.17g %.17g' % (q, x4, x5) for q in xyz])[0]
              for x4, x5 in values]
    changes = [1.0 - overlap(a, b) for a, b in zip(frames, frames[1:])]
    median = statistics.median(changes) if changes else 0.0
    worst = max(range(len(changes)), key=changes.__getitem__) if changes else 0
    ratio = changes[worst] / median if median > 0 else (0.0 if not changes or changes[worst] == 0 else float('inf'))
    print('\nmovie: %d frames of %s on a %d^3 grid: change from frame to frame (1 - overlap)'
          % (len(frames), manifest, n))
    print('  median %.4f, largest %.4f (frame %d -> %d, x4 %.3f x5 %.3f), largest/median %.1f %s'
          % (median, changes[worst] if changes else 0, worst, worst + 1, values[worst][0],
             values[worst][1], ratio, 'PASS' if ratio <= 3 else 'MISS (goal 3)'))
    return {'manifest': str(manifest), 'grid': n, 'values': values, 'changes': changes,
            'median': median, 'largest': changes[worst] if changes else 0, 'largest_frame': worst,
            'ratio': ratio}


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('--model', default=str(HERE / 'meta5d.hf'))
    p.add_argument('--object', default='meta5d', help='the 5-D object (default meta5d)')
    p.add_argument('--frepkit')
    p.add_argument('--grid', type=int, default=64, help='volume samples per axis (default 64)')
    p.add_argument('--mesh-grid', type=int, default=128,
                   help='mesh samples per axis, as the spreadsheet (default 128; 0: no meshes)')
    p.add_argument('--frames', help="a manifest.json whose frames' x4, x5 the movie measure follows")
    p.add_argument('--movie-grid', type=int, default=32, help='movie samples per axis (default 32)')
    p.add_argument('--json', help='write every number to this file')
    argv = sys.argv[1:]
    if '--' in argv:
        EXTRA.extend(argv[argv.index('--') + 1:])
        argv = argv[:argv.index('--')]
    args = p.parse_args(argv)
    frepkit = find_frepkit(args.frepkit)
    model = pathlib.Path(args.model).resolve()

    points = grid_points(args.grid)
    xyz = ['%.9g %.9g %.9g' % q for q in points]
    keys = {}
    for obj, _ in KEYS:
        keys[obj], errors = evaluate(frepkit, model, obj, xyz)
        if errors:
            print('%s: %d points with run-time errors (counted outside)' % (obj, errors))
    cells = []
    for x5 in STEPS:
        for x4 in STEPS:
            lines = ['%s %g %g' % (q, x4, x5) for q in xyz]
            inside, errors = evaluate(frepkit, model, args.object, lines)
            n_in = sum(inside)
            cell = {'x4': x4, 'x5': x5, 'volume_permille': 1000.0 * n_in / len(inside),
                    'errors': errors, 'keys_percent': {}, 'overlap': {}}
            for obj, _ in KEYS:
                k = keys[obj]
                both = sum(1 for a, b in zip(inside, k) if a and b)
                cell['keys_percent'][obj] = 100.0 * both / max(1, sum(k))
                cell['overlap'][obj] = overlap(inside, k)
            cells.append(cell)
    if args.mesh_grid > 0:
        with tempfile.TemporaryDirectory() as work:
            for cell in cells:
                t, c, l = mesh_statistics(frepkit, model, args.object, cell['x4'], cell['x5'],
                                          args.mesh_grid, work)
                cell.update(triangles=t, components=c, largest_share=l)

    def rows(f):
        return [[f(cells[5 * r + c]) for c in range(5)] for r in range(5)]

    print('%s, volume on a %d^3 grid of [-10, 10]^3, meshes at %d^3' % (model.name, args.grid, args.mesh_grid))
    for obj, name in KEYS:
        print('  %-8s inside: %5.1f per mille of the box' % (name, 1000.0 * sum(keys[obj]) / len(points)))
    table('inside volume, per mille of the box', rows(lambda c: c['volume_permille']), '%9.1f')
    for obj, name in KEYS:
        table('%% of %s inside the cell' % name, rows(lambda c, o=obj: c['keys_percent'][o]), '%9.0f')
    for obj, name in KEYS:
        table('overlap with %s (intersection over union)' % name,
              rows(lambda c, o=obj: c['overlap'][o]), '%9.2f')
    if args.mesh_grid > 0:
        table('triangles', rows(lambda c: c['triangles']), '%9d')
        table('components', rows(lambda c: c['components']), '%9d')
        table("largest component's share of the volume, %", rows(lambda c: 100 * c['largest_share']), '%9.0f')
    vols = [c['volume_permille'] for c in cells]
    mid = cells[12]
    print('\nsummary: volume per mille min %.1f (x4 = %g, x5 = %g), median %.1f, max %.1f, max/min %.1f'
          % (min(vols), cells[vols.index(min(vols))]['x4'], cells[vols.index(min(vols))]['x5'],
             statistics.median(vols), max(vols), max(vols) / max(min(vols), 1e-9)))
    edge = [cells[20 + i]['volume_permille'] for i in (1, 2, 3)]
    print('         NiHon-Rob_let edge (x5 = 1, x4 = 0.25..0.75): %s per mille'
          % ', '.join('%.1f' % v for v in edge))
    print('         the (0.5, 0.5) cell shows %s' % ', '.join(
        '%.0f%% of %s' % (mid['keys_percent'][o], n) for o, n in KEYS))
    goals(cells)
    film = movie(frepkit, model, args.object, args.frames, args.movie_grid) if args.frames else None
    if args.json:
        pathlib.Path(args.json).write_text(json.dumps({'model': str(model), 'grid': args.grid,
                                                       'mesh_grid': args.mesh_grid, 'cells': cells,
                                                       'movie': film}, indent=1))


if __name__ == '__main__':
    main()
