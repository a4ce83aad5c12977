#!/usr/bin/python3
"""random_sweep.py -- the guarantee on random valid domains, in bounded time (issue 24).

Usage:
    random_sweep.py QUAD_MESHER OUT_DIR --seed S --count N [--kinds star,twoopt,convex]
                    [--jobs 2] [--timeout 15] [--verifier PATH] [--keep-meshes]

Draws domains 0 to N-1 of seed S with random_domains.py (OUT_DIR/<kind>_<S>_<i>.poly), meshes
each with `QUAD_MESHER IN.poly -o IN.msh --report IN.json` under a time-out, and checks what
was written with the independent verifier (`verify_mesh.py IN.msh --domain IN.poly
--no-overlap --excuse-above 360 --json`; by default <repository>/../shared/bench/verify_mesh.py,
run with this script's Python). An angle outside [45, 135] is excused only at an input corner
sharper than 45 degrees (--excuse-below, the verifier's default): a reflex corner forces none,
as the mesher's own check has it. Each run ends as one of
  PASS          exit 0 and every verifier check ok;
  angles out    exit 0 or 4 (the mesher's own count of angles out), the verifier's
                angles_45_135 check fails (an unexcused angle);
  other checks  exit 0 or 4, the angles pass but another verifier check fails;
  refused       any other exit status (its mesh, if any, is verified too, into the CSV);
  timeout       still running after --timeout seconds (killed);
  crash         killed by a signal.
Prints each run that does not pass as it ends, then a table per kind, per feature and in all
(runs, the six outcomes, median and longest mesher wall time) and the refusals' messages by
their first words. Writes OUT_DIR/results.csv (one row a domain: how it was made, outcome,
exit, seconds, quads, the mesher's and the verifier's count of angles out, the failed checks,
the message) and copies every input that does not pass into OUT_DIR/failing/ (emptied
first). The meshes of passing runs are deleted unless --keep-meshes. Exit status 0: it is a
measurement. Needs Debian's python3-numpy, python3-shapely (and the verifier's
python3-scipy and python3-meshio); run with /usr/bin/python3.
"""
import argparse
import csv
import json
import os
import re
import shutil
import signal
import statistics
import subprocess
import sys
import time
from collections import Counter
from concurrent.futures import ThreadPoolExecutor

import random_domains

OUTCOMES = ('PASS', 'angles out', 'other checks', 'refused', 'timeout', 'crash')
DEFAULT_VERIFIER = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                 '..', '..', 'shared', 'bench', 'verify_mesh.py'))
CSV_FIELDS = ('file', 'kind', 'shape', 'outer_vertices', 'holes', 'hole_vertices', 'feature', 'feature_detail',
              'scale', 'offset_x', 'offset_y', 'outcome', 'exit', 'seconds', 'quads', 'mesher_unforced_quads',
              'verifier_unexcused_angles', 'failed_checks', 'message')


def remove_if_there(path):
    if os.path.exists(path):
        os.remove(path)


def mesher_command(mesher, poly, options=()):
    """`mesher poly options -o IN.msh --report IN.json`, IN being poly without .poly."""
    stem = poly[:-len('.poly')]
    return [mesher, poly] + list(options) + ['-o', stem + '.msh', '--report', stem + '.json']


def run_mesher(mesher, poly, timeout, options=()):
    """Runs mesher_command(mesher, poly, options): (exit status or None on time-out, the lines of
    its stderr, seconds)."""
    stem = poly[:-len('.poly')]
    for old in (stem + '.msh', stem + '.json'):
        remove_if_there(old)
    start = time.monotonic()
    try:
        run = subprocess.run(mesher_command(mesher, poly, options), capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, [], time.monotonic() - start
    return run.returncode, run.stderr.strip().splitlines(), time.monotonic() - start


def verifier_command(verifier, poly, options=()):
    """`verify_mesh.py IN.msh --domain poly --no-overlap options --json` with this script's Python."""
    return ([sys.executable, verifier, poly[:-len('.poly')] + '.msh', '--domain', poly, '--no-overlap']
            + list(options) + ['--json'])


def run_verifier(verifier, poly, options, timeout):
    """The verifier's JSON report on poly's mesh, or {'failed_checks': [why]} if it gave none."""
    try:
        run = subprocess.run(verifier_command(verifier, poly, options), capture_output=True, text=True,
                             timeout=timeout)
    except subprocess.TimeoutExpired:
        return {'failed_checks': ['verifier timeout']}
    try:
        return json.loads(run.stdout)
    except ValueError:
        return {'failed_checks': ['verifier exit %d' % run.returncode]}


QUADS_OUT = 4  # the mesher's exit status for a mesh written with unforced angles out


def outcome_of(status, report):
    if status is None:
        return 'timeout'
    if status < 0:
        return 'crash'
    if status not in (0, QUADS_OUT):
        return 'refused'
    if report.get('pass'):
        return 'PASS'
    return 'angles out' if 'angles_45_135' in report['failed_checks'] else 'other checks'


def mesher_unforced_quads(poly):
    """The report's count of quads with an angle out that no input corner forces, or ''."""
    try:
        report = json.load(open(poly[:-len('.poly')] + '.json'))
    except (OSError, ValueError):
        return ''
    return report['buffer']['quads_outside_45_135_not_forced']


def sweep_one(args, index):
    """Draws, meshes and verifies domain `index`: its CSV row."""
    poly, made = random_domains.write_domain(args.out_dir, args.seed, index, args.kinds)
    return mesh_and_verify(args, poly, made, args.excuse_above)


def mesh_and_verify(args, poly, made, excuse_above=360):
    """Meshes `poly` and verifies the mesh written (`--excuse-above`): its CSV row, `made` and the
    run's outcome. A passing mesh is removed unless args.keep_meshes."""
    status, lines, seconds = run_mesher(args.mesher, poly, args.timeout)
    message = lines[-1] if lines else ''
    mesh_written = os.path.exists(poly[:-len('.poly')] + '.msh')
    report = (run_verifier(args.verifier, poly, ['--excuse-above', str(excuse_above)], args.verify_timeout)
              if mesh_written else {})
    outcome = outcome_of(status, report)
    if status is not None and status < 0:
        message = 'signal %s' % signal.Signals(-status).name
    if outcome == 'PASS' and not args.keep_meshes:
        remove_if_there(poly[:-len('.poly')] + '.msh')
    return dict(made, file=os.path.basename(poly), outcome=outcome, exit='' if status is None else status,
                seconds='%.3f' % seconds, quads=report.get('n_quads', ''),
                mesher_unforced_quads=mesher_unforced_quads(poly),
                verifier_unexcused_angles=report.get('n_angles_outside_45_135_unexcused', ''),
                failed_checks=' '.join(report.get('failed_checks', [])), message=message)


def message_key(message):
    """The first four words of a message without 'quad-mesher: FILE: ', numbers as '#'."""
    words = re.sub(r'^quad-mesher: (\S+\.poly: )?', '', message).split()[:4]
    return ' '.join('#' if re.search(r'\d', w) else w for w in words) or '(no message)'


def print_run(row):
    print('%s: %s (exit %s, %ss)%s%s' % (row['file'], row['outcome'], row['exit'] if row['exit'] != '' else '-',
                                          row['seconds'], ': ' + row['failed_checks'] if row['failed_checks'] else '',
                                          ': ' + row['message'] if row['message'] else ''))
    sys.stdout.flush()


def print_table(rows, key, title, outcomes=OUTCOMES):
    """One line per value of row[key] and one for all: runs, outcomes, median and max seconds."""
    print('%-12s %5s' % (title, 'runs') + ''.join(' %s' % o for o in outcomes) + ' %8s %8s' % ('median s', 'max s'))
    groups = sorted(set(row[key] for row in rows))
    for name, group in [(g, [r for r in rows if r[key] == g]) for g in groups] + [('all', rows)]:
        counts = Counter(r['outcome'] for r in group)
        seconds = [float(r['seconds']) for r in group]
        print('%-12s %5d' % (name, len(group)) + ''.join(' %*d' % (len(o), counts[o]) for o in outcomes)
              + ' %8.2f %8.2f' % (statistics.median(seconds), max(seconds)))


def print_messages(rows):
    refused = [r for r in rows if r['outcome'] == 'refused']
    if not refused:
        return
    print('refusals by message:')
    keys = Counter(message_key(r['message']) for r in refused)
    for key, count in keys.most_common():
        example = next(r for r in refused if message_key(r['message']) == key)
        print('  %4d  %s    e.g. %s: %s' % (count, key, example['file'], example['message']))


def write_results(rows, out_dir, fields=CSV_FIELDS):
    """OUT_DIR/results.csv, and the inputs of the runs that do not pass copied into OUT_DIR/failing/
    (emptied first)."""
    with open(os.path.join(out_dir, 'results.csv'), 'w', newline='') as out:
        writer = csv.DictWriter(out, fields, extrasaction='ignore')
        writer.writeheader()
        writer.writerows(rows)
    failing = os.path.join(out_dir, 'failing')
    shutil.rmtree(failing, ignore_errors=True)
    os.makedirs(failing)
    for row in rows:
        if row['outcome'] != 'PASS':
            shutil.copy(os.path.join(out_dir, row['file']), failing)


def add_sweep_arguments(parser, timeout):
    """The arguments every sweep takes but the domains': mesher, out_dir, jobs, time-outs, verifier."""
    parser.add_argument('mesher')
    parser.add_argument('out_dir')
    parser.add_argument('--jobs', type=int, default=2)
    parser.add_argument('--timeout', type=float, default=timeout, help='seconds a mesher run may take')
    parser.add_argument('--verify-timeout', type=float, default=300, help='seconds a verifier run may take')
    parser.add_argument('--verifier', default=DEFAULT_VERIFIER, help='verify_mesh.py (default %(default)s)')
    parser.add_argument('--keep-meshes', action='store_true', help='keep the meshes of passing runs too')


def sweep_and_report(args, one, fields, tables):
    """sweep(args, one), its rows written (write_results()) and printed: a table per (key, title)
    of `tables`, then the refusals by message."""
    rows = sweep(args, one)
    write_results(rows, args.out_dir, fields)
    if not rows:
        return rows
    for key, title in tables:
        print()
        print_table(rows, key, title)
    print_messages(rows)
    return rows


def sweep_written_domains(doc, write, fields, tables, timeout=60, options=()):
    """The main of a sweep over domains that `write(out_dir, seed, index, kinds, **values)` draws
    and writes (returning the .poly's path and how it was made): its arguments read as
    add_sweep_arguments() and random_domains.add_domain_arguments() define them, plus
    `options`, (flag, add_argument's keywords) pairs whose values `write` takes by their dest
    names; `doc` the help's first line."""
    parser = argparse.ArgumentParser(description=doc.split('\n')[0])
    add_sweep_arguments(parser, timeout)
    random_domains.add_domain_arguments(parser)
    dests = [parser.add_argument(flag, **keywords).dest for flag, keywords in options]
    args = parser.parse_args()

    def one(args, index):
        values = {dest: getattr(args, dest) for dest in dests}
        poly, made = write(args.out_dir, args.seed, index, args.kinds, **values)
        return mesh_and_verify(args, poly, made)
    sweep_and_report(args, one, fields, tables)
    return 0


def sweep(args, one):
    """one(args, index) for the domains 0 to args.count - 1 on args.jobs threads, in order; prints
    each run that does not pass as it ends. Returns the rows."""
    os.makedirs(args.out_dir, exist_ok=True)
    rows = []
    with ThreadPoolExecutor(args.jobs) as pool:
        for row in pool.map(lambda index: one(args, index), range(args.count)):
            rows.append(row)
            if row['outcome'] != 'PASS':
                print_run(row)
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    add_sweep_arguments(parser, timeout=15)
    random_domains.add_domain_arguments(parser)
    parser.add_argument('--excuse-above', type=float, default=360,
                        help="the verifier's --excuse-above: 360 excuses no reflex corner (default)")
    args = parser.parse_args()
    rows = sweep_and_report(args, sweep_one, CSV_FIELDS, [('kind', 'kind'), ('feature', 'feature')])
    if not rows:
        return 0
    print('per-domain results: %s; failing inputs: %s'
          % (os.path.join(args.out_dir, 'results.csv'), os.path.join(args.out_dir, 'failing')))
    return 0


if __name__ == '__main__':
    sys.exit(main())
