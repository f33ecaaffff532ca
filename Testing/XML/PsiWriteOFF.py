"""Writes the GUI test's dataset: a tetrahedral .off mesh (the literature's format, read by the
plugin's vtkPsiOFFTetReader) of a 7x7x7-point cube cut into Kuhn tetrahedra (6 per cell), with a
Gaussian blob plus a ramp as the scalar. Usage (from the GUI's Python shell):
runpy.run_path('PsiWriteOFF.py')['write'](path)."""


def write(path, n=7):
    import math
    pts = []
    for k in range(n):
        for j in range(n):
            for i in range(n):
                x, y, z = (2.0 * i / (n - 1) - 1, 2.0 * j / (n - 1) - 1, 2.0 * k / (n - 1) - 1)
                s = 100.0 * math.exp(-3.0 * (x * x + y * y + z * z)) + 20.0 * x
                pts.append((x, y, z, s))
    perms = ((0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0))
    tets = []
    for k in range(n - 1):
        for j in range(n - 1):
            for i in range(n - 1):
                for p in perms:
                    c = [i, j, k]
                    ids = [c[0] + n * (c[1] + n * c[2])]
                    for axis in p:
                        c[axis] += 1
                        ids.append(c[0] + n * (c[1] + n * c[2]))
                    tets.append(ids)
    with open(path, "w") as f:
        f.write("%d %d\n" % (len(pts), len(tets)))
        for p in pts:
            f.write("%.6f %.6f %.6f %.6f\n" % p)
        for t in tets:
            f.write("%d %d %d %d\n" % tuple(t))
    print("PsiWriteOFF: %d points, %d tetrahedra -> %s" % (len(pts), len(tets), path))
