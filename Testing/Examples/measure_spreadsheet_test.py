#!/usr/bin/env python3
"""Examples/homotopic/measure_spreadsheet.py runs and measures what it says: on a coarse grid,
25 cells; each corner cell overlaps its own key exactly (1.0: Meta5D's corners are the keys, bit
for bit) and the opposite key less; every overlap and share is a fraction; the goals are printed.

  measure_spreadsheet_test.py SCRIPT FREPKIT"""
import json
import subprocess
import sys
import tempfile


def main():
    script, frepkit = sys.argv[1:3]
    frames = [(0, 0), (0, 0), (1, 0), (0.5, 0.5)]
    manifest = {'files': [{'kind': 'frames', 'frames': [{'values': {'x4': a, 'x5': b}} for a, b in frames]}]}
    with tempfile.NamedTemporaryFile(suffix='.json') as out, \
            tempfile.NamedTemporaryFile('w', suffix='.json') as frames_file:
        json.dump(manifest, frames_file)
        frames_file.flush()
        run = subprocess.run([sys.executable, script, '--frepkit', frepkit, '--grid', '12',
                              '--mesh-grid', '16', '--frames', frames_file.name, '--movie-grid', '10',
                              '--json', out.name],
                             capture_output=True, text=True)
        if run.returncode != 0:
            print(run.stdout, run.stderr)
            return 1
        measured = json.load(open(out.name))
        cells, movie = measured['cells'], measured['movie']
    failures = []
    changes = movie['changes']
    if len(changes) != 3 or changes[0] != 0.0 or not 0.0 < changes[1] <= 1.0:
        failures.append('movie changes %s: expected 0 between the equal frames, then a change' % changes)
    if movie['largest_frame'] not in (1, 2) or movie['largest'] != max(changes):
        failures.append('movie largest change %s at %s' % (movie['largest'], movie['largest_frame']))
    if 'movie:' not in run.stdout or (' PASS' not in run.stdout.split('movie:')[1]
                                      and ' MISS' not in run.stdout.split('movie:')[1]):
        failures.append('the movie goal is not printed')
    if len(cells) != 25:
        failures.append('%d cells' % len(cells))
    corners = {(0, 0): 'cat', (1, 0): 'robot', (0, 1): 'nihon', (1, 1): 'roblet'}
    for c in cells:
        for key, overlap in c['overlap'].items():
            if not 0.0 <= overlap <= 1.0:
                failures.append('cell (%g, %g): overlap with %s is %g' % (c['x4'], c['x5'], key, overlap))
        own = corners.get((c['x4'], c['x5']))
        if own and c['overlap'][own] != 1.0:
            failures.append('corner (%g, %g) overlaps %s %g, not 1' % (c['x4'], c['x5'], own, c['overlap'][own]))
        if own and min(c['overlap'].values()) >= 1.0:
            failures.append('corner (%g, %g) overlaps every key fully' % (c['x4'], c['x5']))
        if c.get('components', 0) < 1:
            failures.append('cell (%g, %g) has no mesh component' % (c['x4'], c['x5']))
    if run.stdout.count(' PASS') + run.stdout.count(' MISS') != 6:
        failures.append('the five goals are not printed:\n' + run.stdout[-600:])
    for f in failures:
        print('FAIL:', f)
    print('%d cells checked, %d failures' % (len(cells), len(failures)))
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
