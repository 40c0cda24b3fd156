#!/usr/bin/env python3
"""The k-ε channel's diffusion sums next to the walls against the 1-D solver's fluxes.

    channel_ke_diffusion.py NF MODE SNAPSHOT.h5 [SNAPSHOT.h5 ...]

For each particle row of a cases/channel_ke.lua run with NF rows (the first row at y_p = 0.05, the
boundary offset y_p - dr/2, periodic length as the case makes it) the script evaluates the
diffusion sums of k and epsilon that wcr_turb_transport forms (Wang, Sun & Hu eqs 23-24:
2 sum_j D_ij (phi_i - phi_j) F_ij V_j / lambda over the fluid neighbours, Wendland C2 at
h = 1.3 dr, lambda the lattice's Laplacian sum) and compares their row means with the 1-D
solver's finite differences on the rows' mean fields (tests/reference/channel1d.c with `rows`:
the flux through each face with the faces' mean nu_t, none through the wall below the first row).
MODE: 0 the paper's sums (the harmonic mean of D), 1 the logarithmic mean, 2 the wall's mirror
images (the first rows' pairs with their neighbours' images behind the boundary), 3 both
(wcsph-riemann's turbulent_diffusion = "log_mirror"). Several snapshots are pooled.

Read with h5dump (no h5py); a row of ratios per particle row: the particles' sum over the 1-D
solver's for k and for epsilon. On the start from the 1-D solver's own solution (channel_ke
init = 2, snap_000000.h5) the first row reads 0.832 / 0.932 (MODE 0 / 3) at NF = 20, as the
case's k_row1_diffusion does from the first step (tests/case.cmake, run_channel_ke_diffusion).
"""
import math
import subprocess
import sys
import tempfile


def dataset(path, name):
    with tempfile.NamedTemporaryFile(mode="r", suffix=".txt") as tmp:
        subprocess.run(["h5dump", "-d", name, "-y", "-w", "0", "-o", tmp.name, path],
                       capture_output=True, text=True, check=True)
        return [float(t) for t in open(tmp.name).read().replace(",", " ").split()]


def main(argv):
    if len(argv) < 4:
        sys.exit(__doc__)
    nf, mode, files = int(argv[1]), int(argv[2]), argv[3:]
    if nf < 6 or mode not in (0, 1, 2, 3):
        sys.exit("channel_ke_diffusion.py: NF must be at least 6 and MODE 0, 1, 2 or 3")
    y_p, nu, height = 0.05, 1e-4, 2.0
    dr = (height - 2 * y_p) / (nf - 1)
    h = 1.3 * dr
    off = y_p - dr / 2
    length = max(int(1.0 / dr + 0.5), 8) * dr

    def f_kernel(r):  # W'/r of the 2-D Wendland C2 kernel
        q = r / h
        return -35 / (4 * math.pi * h ** 4) * (1 - q / 2) ** 3 if q < 2 else 0.0

    lam = sum(-f_kernel(math.hypot(a, b) * dr) * (b * dr) ** 2 * dr * dr
              for a in range(-4, 5) for b in range(-4, 5) if a or b)

    def mean(a, b):
        if mode & 1:  # the logarithmic mean (a - b)/ln(a/b)
            m, x = (a + b) / 2, (a - b) / (a + b)
            return m if abs(x) < 1e-9 else m * x / math.atanh(x)
        return 2 * a * b / (a + b)

    rows = {}
    for path in files:
        pos = dataset(path, "/particles/pos")
        kind = dataset(path, "/particles/kind")
        vol = dataset(path, "/particles/vol")
        k = dataset(path, "/particles/k")
        eps = dataset(path, "/particles/epsilon")
        nut = dataset(path, "/particles/nu_t")
        fluid = [i for i in range(len(kind)) if kind[i] == 0]

        def height_of(i):  # over the nearer boundary
            y = pos[2 * i + 1]
            return min(y - off, height - off - y)

        for i in fluid:
            d = height_of(i)
            row = int(d // dr)
            if row > 8:
                continue
            dk = de = 0.0
            for j in fluid:
                if j == i:
                    continue
                rx = pos[2 * i] - pos[2 * j]
                rx -= length * round(rx / length)
                ry = pos[2 * i + 1] - pos[2 * j + 1]
                r = math.hypot(rx, ry)
                if r >= 2 * h:
                    continue
                f = f_kernel(r) * vol[j]
                dj = height_of(j)
                same_wall = (pos[2 * i + 1] < height / 2) == (pos[2 * j + 1] < height / 2)
                if mode & 2 and same_wall and d + dj < 2 * h:  # j's image behind the boundary
                    f += f_kernel(math.hypot(rx, d + dj)) * vol[j]
                dk += 2 * mean(nu + nut[i], nu + nut[j]) * (k[i] - k[j]) * f
                de += 2 * mean(nu + nut[i] / 1.3, nu + nut[j] / 1.3) * (eps[i] - eps[j]) * f
            acc = rows.setdefault(row, [0, 0.0, 0.0, 0.0, 0.0, 0.0])
            for q, v in enumerate((1, dk / lam, de / lam, k[i], eps[i], nut[i])):
                acc[q] += v
    means = {r: [v / a[0] for v in a] for r, a in rows.items()}

    def finite_difference(col, sigma, r):
        c, up = means[r][col], means[r + 1][col]
        flux_up = (nu + (means[r][5] + means[r + 1][5]) / 2 / sigma) * (up - c)
        flux_down = 0.0 if r == 0 else (nu + (means[r][5] + means[r - 1][5]) / 2 / sigma) * (
            c - means[r - 1][col])
        return (flux_up - flux_down) / dr ** 2

    print("row  k: particles' sum, 1-D, ratio | epsilon: particles' sum, 1-D, ratio")
    for r in sorted(means)[:-1]:
        fk, fe = finite_difference(3, 1.0, r), finite_difference(4, 1.3, r)
        print("%3d  %+.4e %+.4e %.3f | %+.4e %+.4e %.3f" % (
            r + 1, means[r][1], fk, means[r][1] / fk, means[r][2], fe, means[r][2] / fe))


if __name__ == "__main__":
    main(sys.argv)
