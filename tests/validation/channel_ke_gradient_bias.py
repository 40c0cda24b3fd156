#!/usr/bin/env python3
"""The k-ε channel's production as wcsph-riemann's kernel sums see the model's own profile.

Lays the 1-D solver's solution on an SPH run's rows (tests/data/channel1d_rowsN.csv:
`channel1d --rows N --bulk-over-rows`, y_p = 0.05, δ = 1) as a periodic lattice of spacing dr,
and takes ∂u/∂y at each row as kernels/wcsph_riemann/turbulence.cl does: the Wendland C2
kernel at h = 1.3 dr (the scheme's), the gradient corrected by B^in over the fluid neighbours
(Wang, Sun & Hu eqs 20, 22, 40), with eq 40's compensation (w_s = 0.1) on the pairs of a wall
layer particle (d < 2h − dr) with the first row, whose ∂U/∂n is the wall function's (eq 13).
Against the 1-D solver's exact ∂u/∂y = u_τ² (1 − y/δ)/(ν + ν_t), the row's production
ν_t (∂u/∂y)² over the model's. The first row's production is eq 13's, not the sums': it is left
out. Prints one line per row: N_f, row, y, gradient ratio, production ratio; then, per N_f, the
production summed over the rows from the second on over the model's.

--log-rows M: the rows 2 to M take the gradient in the log law's coordinate instead, the pair's
wall-normal separation y_i − y_j replaced by y_i ln(y_i/y_j) in the moment sum (exact for
u = a ln y + b; y from the physical wall), and without eq 40's compensation: what a log-aware
kernel gradient next to the walls would leave of the bias (an a-priori test: no kernel has it).

usage: channel_ke_gradient_bias.py [DATA_DIR] [--log-rows M] [N_f ...]   (default tests/data,
       20 40 80)
"""
import csv
import math
import sys

NU, YP, KAPPA, E, CMU, WS = 1e-4, 0.05, 0.41, 9.793, 0.09, 0.1


def load(path):
    with open(path) as f:
        lines = f.readlines()
    header = lines[1]
    u_tau = float(header.split("u_tau = ")[1].split(",")[0])
    rows = list(csv.DictReader(line for line in lines if not line.startswith("#")))
    return u_tau, rows


def wendland_f(r, h):
    """(1/r) dW/dr of Wendland C2 in 2-D, up to its normalisation (it cancels in B^in)."""
    q = r / h
    if q >= 2.0:
        return 0.0
    return -5.0 * (1.0 - q / 2.0) ** 3 / (h * h)  # dW/dq = −5 q (1 − q/2)³, q/r = 1/h


def bias(nf, data_dir, log_rows=0):
    u_tau, rows = load(f"{data_dir}/channel1d_rows{nf}.csv")
    ys = [float(r["y"]) for r in rows]
    us = [float(r["u"]) for r in rows]
    ks = [float(r["k"]) for r in rows]
    nts = [float(r["nu_t"]) for r in rows]
    n = len(ys)
    dr = (2.0 - 2.0 * YP) / (nf - 1)
    h = 1.3 * dr
    reach = int(2.0 * h / dr) + 1
    r_ext = 2.0 * h - dr
    # the wall function's ∂U/∂n on the first row (eq 13: U/(u+ κ y_p), u_s = C_μ^¼ k^½)
    us1 = CMU ** 0.25 * math.sqrt(ks[0])
    dudn1 = us[0] / (math.log(E * YP * us1 / NU) * YP)

    def u_at(row):  # the other half mirrored across the centre line
        return us[row] if row < n else us[2 * n - 1 - row]

    def y_at(row):
        return ys[row] if row < n else 2.0 - ys[2 * n - 1 - row]

    out = []
    for i in range(1, n):
        d_i = (i + 0.5) * dr  # distance from the offset wall
        in_ext = d_i < r_ext
        ayy, g = 0.0, 0.0
        for dj in range(-reach, reach + 1):
            j = i + dj
            if j < 0:
                continue  # dummies: not in B^in nor in the sum
            for dx in range(-reach, reach + 1):
                rx, ry = dx * dr, (i - j) * dr  # r_ij = x_i − x_j
                r = math.hypot(rx, ry)
                if r == 0.0 or r >= 2.0 * h:
                    continue
                f = wendland_f(r, h)
                vij = us[i] - u_at(j)
                if i + 1 <= log_rows:  # the log law's coordinate: y_i ln(y_i/y_j)
                    ayy -= f * ys[i] * math.log(ys[i] / y_at(j)) * ry
                else:
                    ayy -= f * ry * ry
                    if in_ext and j == 0:  # eq 40: w_s ∇v_p r_ij + (1 − w_s) v_ij
                        vij = WS * dudn1 * ry + (1.0 - WS) * vij
                g += vij * f * ry
        grad = -g / ayy
        exact = u_tau * u_tau * (1.0 - ys[i]) / (NU + nts[i])
        out.append((i + 1, ys[i], grad / exact, (grad / exact) ** 2, nts[i] * exact * exact))
    return out


def main():
    args = sys.argv[1:]
    data_dir = args.pop(0) if args and not args[0].isdigit() and args[0] != "--log-rows" else "tests/data"
    log_rows = 0
    if args and args[0] == "--log-rows":
        if len(args) < 2 or not args[1].isdigit():
            sys.exit("channel_ke_gradient_bias.py: --log-rows needs a row number (2 or more)")
        log_rows = int(args[1])
        args = args[2:]
    for a in args:
        if not a.isdigit():
            sys.exit(f"channel_ke_gradient_bias.py: N_f must be a number of rows, not {a!r}")
    nfs = [int(a) for a in args] or [20, 40, 80]
    print("N_f,row,y,grad_ratio,production_ratio")
    total = {}
    for nf in nfs:
        rows = bias(nf, data_dir, log_rows)
        for row, y, gr, pr, _ in rows:
            print(f"{nf},{row},{y:.4f},{gr:.4f},{pr:.4f}")
        total[nf] = sum(pr * p for *_, pr, p in rows) / sum(p for *_, p in rows)
    for nf in nfs:  # the rows' production summed over the half channel (rows 2 on), over the model's
        print(f"# N_f = {nf}: production over rows 2 on {total[nf]:.4f} of the model's")


if __name__ == "__main__":
    main()
