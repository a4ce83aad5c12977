#!/usr/bin/python3
"""calculix_surface_loads.py QUAD_MESHER WORK_DIR -- the .inp's boundary surfaces carry loads in
CalculiX (Debian's calculix-ccx; exit 77 where it is not installed).

Meshes a 4 x 1 plate whose four sides have markers 1 (bottom), 2 (right), 3 (top) and 4
(left), writes a CalculiX job that includes the .inp, holds side 4 in x and side 1 in y, and
loads the element surfaces marker_2 (a tension of 100) and marker_3 (a pressure of 50) with
*DSLOAD. Every element must then carry the uniform stress sxx = 100, syy = -50, sxy = 0, and
the supports the reactions -100 (x, side 4) and 200 (y, side 1): a face of a surface on the
wrong side of its element would load the plate elsewhere and break both."""
import os
import re
import shutil
import subprocess
import sys

PLATE = """4 2 0 1
1 0 0 1
2 4 0 2
3 4 1 3
4 0 1 4
4 1
1 1 2 1
2 2 3 2
3 3 4 3
4 4 1 4
0
"""

JOB = """*INCLUDE, INPUT=plate.inp
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*SOLID SECTION, ELSET=domain, MATERIAL=STEEL
1.
*BOUNDARY
marker_4, 1, 1
marker_1, 2, 2
*STEP
*STATIC
*DSLOAD
marker_2, P, -100.
marker_3, P, 50.
*NODE PRINT, NSET=marker_4, TOTALS=ONLY
RF
*NODE PRINT, NSET=marker_1, TOTALS=ONLY
RF
*EL PRINT, ELSET=domain
S
*END STEP
"""


def close(a, b, scale):
    return abs(a - b) <= 1e-6 * scale


def main():
    mesher, work = sys.argv[1], sys.argv[2]
    ccx = shutil.which('ccx')
    if ccx is None:
        print('calculix_surface_loads: no ccx (Debian calculix-ccx): skipped')
        return 77
    os.makedirs(work, exist_ok=True)
    with open(os.path.join(work, 'plate.poly'), 'w') as f:
        f.write(PLATE)
    subprocess.run([mesher, 'plate.poly', '-o', 'plate.inp'], cwd=work, check=True)
    with open(os.path.join(work, 'job.inp'), 'w') as f:
        f.write(JOB)
    subprocess.run([ccx, 'job'], cwd=work, check=True, stdout=subprocess.DEVNULL)
    text = open(os.path.join(work, 'job.dat')).read()
    failures = []
    totals = re.findall(r'total force \(fx,fy,fz\) for set (\S+)[^\n]*\n\s*\n\s*(\S+)\s+(\S+)', text)
    forces = {name: (float(fx), float(fy)) for name, fx, fy in totals}
    if not close(forces.get('MARKER_4', (0, 0))[0], -100.0, 100):
        failures.append('reaction in x on side 4: %s, not -100' % (forces.get('MARKER_4'),))
    if not close(forces.get('MARKER_1', (0, 0))[1], 200.0, 200):
        failures.append('reaction in y on side 1: %s, not 200' % (forces.get('MARKER_1'),))
    stresses = text.split('stresses', 1)[1].split('\n')[2:] if 'stresses' in text else []
    points = 0
    for line in stresses:
        fields = line.split()
        if len(fields) != 8:
            continue
        points += 1
        sxx, syy, sxy = float(fields[2]), float(fields[3]), float(fields[5])
        if not (close(sxx, 100.0, 100) and close(syy, -50.0, 100) and close(sxy, 0.0, 100)):
            failures.append('element %s: sxx %g, syy %g, sxy %g' % (fields[0], sxx, syy, sxy))
    if points == 0:
        failures.append('no element stresses in job.dat')
    for message in failures[:10]:
        print('calculix_surface_loads: ' + message)
    print('calculix_surface_loads: %d integration points, reactions %s: %s'
          % (points, forces, 'FAIL' if failures else 'ok'))
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
