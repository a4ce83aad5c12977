#!/usr/bin/python3
"""boundary_layer_sweep.py -- boundary layers on random far fields, in bounded time (issue 25).

Usage:
    boundary_layer_sweep.py QUAD_MESHER OUT_DIR --seed S --count N [--kinds star,twoopt,convex,rectilinear]
                            [--jobs 2] [--timeout 30] [--verifier PATH] [--keep-meshes]

Rerun (about 8 minutes on 2 cores, with --jobs 1 while a build takes the other one; 4 of the 60 runs
reach the time-out):
    /usr/bin/python3 benchmark/boundary_layer_sweep.py build/src/quad-mesher /tmp/blsweep --seed 1 --count 60

Draws far fields 0 to N-1 of seed S with `random_domains.py --far-field` (OUT_DIR/farfield_<kind>_<S>_<i>.poly:
1 to 3 bodies of diameter 1 with their spikes, notches, near-collinear runs and short edges, a tenth
of them with a slot 0.01 to 0.03 wide; by default of all four kinds), and for each the layers from
numpy.random.default_rng([S, i, 25]) alone: N of {1, 2, 3, 5, 10, 20, 40}, H = 10^U(-5, -2) body
sizes, R of {1.0, 1.05, 1.15, 1.3}. Runs `QUAD_MESHER IN.poly --boundary-layers N --first-height H
--growth R -o IN.msh --report IN.json` (the walls: the bodies) under a time-out and checks the mesh
with the independent verifier (`verify_mesh.py IN.msh --domain IN.poly --no-overlap --json`; by
default <repository>/../shared/bench/verify_mesh.py, run with this script's Python). The angles are
the report's angles_in_layers and angles_outside_layers (1e-7 degree slack); the verifier's range of
all angles must agree with them (failed check report_angles if not). Each run ends as one of
  PASS             exit 0, every verifier check but angles_45_135 ok, the layers' angles in
                   [22.5, 157.5] and the other quads' in [45, 135];
  layers excused   as PASS but for layer angles outside [22.5, 157.5] within [a/2, 180 - a/2],
                   a the domain's sharpest corner (a body's notch or other reflex corner over
                   315 degrees): the stacks meet on the corner's bisector, the paper's Fig. 9(a)
                   split that takes its 45-degree floor to 22.5;
  layers out       a layer angle outside [22.5, 157.5] that no corner forces;
  outside excused  the layers' angles in range, another angle outside [45, 135] (or exit 4) in a
                   domain with a corner sharper than 45 degrees;
  outside out      the same with no such corner;
  other checks     exit 0 or 4 (the mesher's own count of angles out), a verifier check other than
                   angles_45_135 fails (or the report has no layers);
  refused          any other exit status, with the first line the mesher wrote to stderr that
                   is not a warning (the message of the other outcomes too);
  timeout          still running after --timeout seconds (killed);
  crash            killed by a signal.
Prints each run that does not pass as it ends, then a table per kind and per N (runs, the nine
outcomes, median and longest mesher wall time), the refusals' messages by their first words, how
many runs have half the sharpest corner as their smallest layer angle (a corner split on its
bisector) and the 10 runs with the worst layer angles (ratio: the smallest over the sharpest
corner). Writes OUT_DIR/results.csv (one row a domain: seed, index, how it was made, N, H, R,
outcome, exit, seconds, quads, the layer angles and that ratio, the outside angles, the layers'
first heights over H and growths (the extremes over the walls), thinned bands and fans, the failed
checks, the message), copies the input of every run that does not pass into OUT_DIR/failing/
(emptied first) with <name>.txt beside it: the command lines that mesh and check it again. The
meshes of passing runs are deleted unless --keep-meshes. Exit status 0: it is a measurement. Needs
Debian's python3-numpy, python3-shapely (and the verifier's python3-scipy and python3-meshio); run
with /usr/bin/python3.
"""
import argparse
import json
import os
import shlex
import signal
import sys

import numpy as np

import random_domains
import random_sweep

OUTCOMES = ('PASS', 'layers excused', 'layers out', 'outside excused', 'outside out', 'other checks', 'refused',
            'timeout', 'crash')
LAYERS = (1, 2, 3, 5, 10, 20, 40)
FIRST_HEIGHT_EXPONENTS = (-5, -2)   # H = 10^U(-5, -2) body sizes
GROWTHS = (1.0, 1.05, 1.15, 1.3)
PARAMETER_STREAM = 25               # the layers of domain i: default_rng([S, i, 25])
LAYER_ANGLES = (22.5, 157.5)
OUTSIDE_ANGLES = (45.0, 135.0)
SLACK = 1e-7                        # degrees
CSV_FIELDS = ('seed', 'index', 'file', 'kind', 'shape', 'bodies', 'body_vertices', 'feature', 'feature_detail',
              'least_gap', 'slot', 'sharpest_corner', 'N', 'H', 'R', 'outcome', 'exit', 'seconds', 'quads',
              'layer_quads', 'layer_angle_min', 'layer_angle_max', 'layer_min_per_corner', 'outside_angle_min',
              'outside_angle_max', 'first_height_min', 'first_height_max', 'growth_min', 'growth_max',
              'thinned_bands', 'fans', 'failed_checks', 'message')


def layer_parameters(seed, index):
    """N, H and R of domain `index` of `seed`."""
    rng = np.random.default_rng([seed, index, PARAMETER_STREAM])
    layers = int(rng.choice(LAYERS))
    height = random_domains.BODY_SIZE * 10 ** rng.uniform(*FIRST_HEIGHT_EXPONENTS)
    return layers, height, float(rng.choice(GROWTHS))


def layer_options(layers, height, growth):
    return ['--boundary-layers', str(layers), '--first-height', repr(height), '--growth', repr(growth)]


def within(interval, bounds):
    return bounds[0] - SLACK <= interval[0] and interval[1] <= bounds[1] + SLACK


def layer_figures(poly, height):
    """The mesher report's boundary_layers figures for the CSV ({} without them); first heights
    as multiples of H."""
    try:
        layers = json.load(open(poly[:-len('.poly')] + '.json'))['boundary_layers']
    except (OSError, ValueError, KeyError):
        return {}
    walls = layers['walls']
    return {'layer_quads': layers['layer_quads'],
            'layer_angles': layers['angles_in_layers'], 'outside_angles': layers['angles_outside_layers'],
            'first_height_min': '%.6g' % (min(w['first_height']['min'] for w in walls) / height),
            'first_height_max': '%.6g' % (max(w['first_height']['max'] for w in walls) / height),
            'growth_min': '%.6g' % min(w['growth']['min'] for w in walls),
            'growth_max': '%.6g' % max(w['growth']['max'] for w in walls),
            'thinned_bands': sum(w['thinned_bands'] for w in walls), 'fans': sum(w['fans'] for w in walls)}


def failed_checks(report, figures):
    """The verifier's failed checks but angles_45_135 ('no mesh' without its report), 'no layers'
    if the mesher's report has none, and 'report_angles' if the verifier's angle range is not the
    report's two ranges together."""
    if not report:
        return ['no mesh']
    failed = [c for c in report.get('failed_checks', []) if c != 'angles_45_135']
    if not figures.get('layer_angles') or not figures.get('outside_angles'):
        return failed + ['no layers']
    low = min(figures['layer_angles'][0], figures['outside_angles'][0])
    high = max(figures['layer_angles'][1], figures['outside_angles'][1])
    if 'angle_min' in report and (abs(report['angle_min'] - low) > SLACK or abs(report['angle_max'] - high) > SLACK):
        failed.append('report_angles')
    return failed


def outcome_of(status, failed, figures, sharpest_corner):
    if status is None:
        return 'timeout'
    if status < 0:
        return 'crash'
    if status not in (0, random_sweep.QUADS_OUT):
        return 'refused'
    if failed:
        return 'other checks'
    layers = figures['layer_angles']
    if not within(layers, LAYER_ANGLES):
        half = sharpest_corner / 2
        forced = half < LAYER_ANGLES[0] and layers[0] >= half - SLACK and layers[1] <= 180 - half + SLACK
        return 'layers excused' if forced else 'layers out'
    if not within(figures['outside_angles'], OUTSIDE_ANGLES) or status == random_sweep.QUADS_OUT:
        return 'outside excused' if sharpest_corner < OUTSIDE_ANGLES[0] else 'outside out'
    return 'PASS'


def sweep_one(args, index):
    """Draws, meshes and verifies far field `index`: its CSV row, with the report's angle ranges and
    the mesher's layer options besides."""
    poly, made = random_domains.write_domain(args.out_dir, args.seed, index, args.kinds, far_field=True)
    layers, height, growth = layer_parameters(args.seed, index)
    options = layer_options(layers, height, growth)
    status, lines, seconds = random_sweep.run_mesher(args.mesher, poly, args.timeout, options)
    mesh_written = os.path.exists(poly[:-len('.poly')] + '.msh')
    report = random_sweep.run_verifier(args.verifier, poly, [], args.verify_timeout) if mesh_written else {}
    figures = layer_figures(poly, height)
    failed = failed_checks(report, figures) if mesh_written or status in (0, random_sweep.QUADS_OUT) else []
    outcome = outcome_of(status, failed, figures, made['sharpest_corner'])
    message = next((line for line in lines if ': warning: ' not in line), lines[0] if lines else '')
    if status is not None and status < 0:
        message = 'signal %s' % signal.Signals(-status).name
    if outcome == 'PASS' and not args.keep_meshes:
        random_sweep.remove_if_there(poly[:-len('.poly')] + '.msh')
    layer_angles, outside_angles = figures.get('layer_angles') or ['', ''], figures.get('outside_angles') or ['', '']
    return dict(made, **figures, seed=args.seed, index=index, file=os.path.basename(poly), N=layers,
                H='%.6g' % height, R=growth, options=options, outcome=outcome, exit='' if status is None else status,
                seconds='%.3f' % seconds, quads=report.get('n_quads', ''),
                layer_angle_min=layer_angles[0], layer_angle_max=layer_angles[1],
                layer_min_per_corner=('' if layer_angles[0] == ''
                                      else '%.6g' % (layer_angles[0] / made['sharpest_corner'])),
                outside_angle_min=outside_angles[0], outside_angle_max=outside_angles[1],
                failed_checks=' '.join(failed), message=message)


def write_reproducers(rows, args):
    """OUT_DIR/failing/<name>.txt for every run that does not pass: how to mesh and check its copy."""
    failing = os.path.join(args.out_dir, 'failing')
    mesher = os.path.abspath(args.mesher)
    for row in rows:
        if row['outcome'] != 'PASS':
            poly = os.path.abspath(os.path.join(failing, row['file']))
            with open(poly[:-len('.poly')] + '.txt', 'w') as out:
                out.write('# %s: %s (exit %s, %ss)%s%s\n' % (
                    row['file'], row['outcome'], row['exit'] if row['exit'] != '' else '-', row['seconds'],
                    ': ' + row['failed_checks'] if row['failed_checks'] else '',
                    ': ' + row['message'] if row['message'] else ''))
                out.write(shlex.join(random_sweep.mesher_command(mesher, poly, row['options'])) + '\n')
                out.write(shlex.join(random_sweep.verifier_command(args.verifier, poly)) + '\n')


def print_worst_layers(rows, count=10):
    """How many runs have half the domain's sharpest corner as their smallest layer angle (the
    corner split on its bisector), then the `count` runs whose layer angles stray farthest from
    90 degrees."""
    measured = [r for r in rows if r['layer_angle_min'] != '']
    halved = [r for r in measured if abs(float(r['layer_min_per_corner']) - 0.5) < 1e-6]
    print('smallest layer angle half the sharpest corner: %d of %d runs with layers (%d of them layers out)'
          % (len(halved), len(measured), sum(r['outcome'] == 'layers out' for r in halved)))
    measured.sort(key=lambda r: -max(90 - r['layer_angle_min'], r['layer_angle_max'] - 90))
    print('worst layer angles:')
    print('  %-32s %-15s %3s %8s %5s %17s %17s %8s %6s  %s'
          % ('file', 'outcome', 'N', 'H', 'R', 'layers', 'outside', 'sharpest', 'ratio', 'features'))
    for r in measured[:count]:
        print('  %-32s %-15s %3d %8.2g %5g %17s %17s %8.3g %6.3f  %s'
              % (r['file'], r['outcome'], r['N'], float(r['H']), r['R'],
                 '[%.2f, %.2f]' % (r['layer_angle_min'], r['layer_angle_max']),
                 '[%.2f, %.2f]' % (r['outside_angle_min'], r['outside_angle_max']), r['sharpest_corner'],
                 float(r['layer_min_per_corner']), r['feature']))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    random_sweep.add_sweep_arguments(parser, timeout=30)
    random_domains.add_domain_arguments(parser, random_domains.ALL_KINDS)
    args = parser.parse_args()
    rows = random_sweep.sweep(args, sweep_one)
    random_sweep.write_results(rows, args.out_dir, CSV_FIELDS)
    write_reproducers(rows, args)
    if not rows:
        return 0
    print()
    random_sweep.print_table(rows, 'kind', 'kind', OUTCOMES)
    print()
    random_sweep.print_table(rows, 'N', 'N', OUTCOMES)
    random_sweep.print_messages(rows)
    print()
    print_worst_layers(rows)
    print('per-domain results: %s; failing inputs: %s'
          % (os.path.join(args.out_dir, 'results.csv'), os.path.join(args.out_dir, 'failing')))
    return 0


if __name__ == '__main__':
    sys.exit(main())
