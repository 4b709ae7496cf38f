#!/usr/bin/env python3
"""An IR-ceiling simulator independent of rfir-sim, written from the text-log
format alone (docs/textlog.md), as an outside user would: a differential robot
on a loop under a grid of ceiling emitters (repeated single-code IDs and
unique two-code IDs), two photodiodes, decoded `ir` records at 10 Hz with the
thesis' voltage curve (eq. 5.3) plus noise, and these faults:
failed emitters, a moved emitter, wrong codes and voltage outliers.
Writes NAME.txt (textlog 1), NAME.emitters.txt (the map as the user has it:
the moved emitter where it was) and NAME.gt.tum. Standard library only; see
scripts/crosscheck_ir.sh."""
import argparse, math, random

import simargs

ap = argparse.ArgumentParser()
ap.add_argument("--out", required=True, help="output prefix")
ap.add_argument("--seed", type=int, default=1)
ap.add_argument("--area", default="3.2x2.4", help="floor W x H, m")
ap.add_argument("--pitch", type=float, default=0.8, help="emitter grid pitch, m")
ap.add_argument("--laps", type=int, default=3)
ap.add_argument("--speed", type=float, default=0.2, help="m/s")
ap.add_argument("--failed", type=int, default=0, help="emitters that never answer")
ap.add_argument("--moved", type=float, default=0.0, help="one emitter this far (m) from the map")
ap.add_argument("--wrong-code", type=float, default=0.0, help="share of readings with one code wrong")
ap.add_argument("--volt-outliers", type=float, default=0.0, help="share of wild voltages (0-4 V)")
a = ap.parse_args()
rng = random.Random(a.seed)
W, H = simargs.area(ap, a.area, "3.2x2.4")
simargs.positive(ap, a, ("pitch", "laps", "speed"))
if W <= 1.0 or H <= 1.0:
    ap.error("--area: each side must exceed 1 m (the loop keeps 0.4 m margins)")
C2, C1, C0, RADIUS = -32.7, 2.855, 1.81997, 0.28  # eq. 5.3 in metres, its zero

pairs = [f"{i}{j}" for i in range(5, 10) for j in range(i + 1, 10)]
emitters, n = [], 0
y = a.pitch / 2
while y < H:
    x = a.pitch / 2
    while x < W:
        eid = str(1 + (n // 2) % 4) if n % 2 == 0 else pairs[(n // 2) % len(pairs)]
        emitters.append([eid, x, y, 1.5])
        n += 1
        x += a.pitch
    y += a.pitch
true_pos = [e[1:3] for e in emitters]
if a.failed + (a.moved > 0) > len(emitters):
    ap.error(f"--failed and --moved need more than the {len(emitters)} emitters")
idx = list(range(len(emitters)))
rng.shuffle(idx)
failed = set(idx[:a.failed])
moved = idx[a.failed] if a.moved > 0 else None
if moved is not None:
    b = rng.uniform(-math.pi, math.pi)
    true_pos[moved] = [emitters[moved][1] + a.moved * math.cos(b),
                       emitters[moved][2] + a.moved * math.sin(b)]
receivers = [("pdL", 0.0, 0.15, 0.3), ("pdR", 0.0, -0.15, 0.3)]

m = 0.4
corners = [(m, m), (W - m, m), (W - m, H - m), (m, H - m)]
x, y, th = m, m, 0.0
ox, oy, oth = 0.0, 0.0, 0.0
lines = ["format textlog 1", f"# foreign IR simulator seed {a.seed}"]
for r in receivers:
    lines.append(f"receiver {r[0]} {r[1]} {r[2]} {r[3]}")
lines.append(f"start {x} {y} {th}")
gt, t, dt = [], 0.0, 0.1
route = [corners[(i + 1) % 4] for i in range(4 * a.laps)]

def wrap(v):
    return math.atan2(math.sin(v), math.cos(v))

def readings(T):
    c, s = math.cos(th), math.sin(th)
    for r in receivers:
        rx, ry = x + c * r[1] - s * r[2], y + s * r[1] + c * r[2]
        for k, e in enumerate(emitters):
            if k in failed:
                continue
            d = math.hypot(true_pos[k][0] - rx, true_pos[k][1] - ry)
            if d >= RADIUS:
                continue
            v = max(0.0, C2 * d * d + C1 * d + C0 + rng.gauss(0, 0.03))
            if rng.random() < a.volt_outliers:
                v = rng.uniform(0, 4)
            codes = sorted(set(e[0]))
            if rng.random() < a.wrong_code:
                i = rng.randrange(len(codes))
                codes[i] = str(rng.choice([q for q in range(1, 10) if str(q) not in codes]))
                codes = sorted(set(codes))
            lines.append(f"ir {T:.4f} {r[0]} {','.join(codes)} {v:.4f}")

gi = 0
while gi < len(route):
    gt.append((t, x, y, th))
    lines.append(f"odom {t:.4f} {ox:.6f} {oy:.6f} {wrap(oth):.6f}")
    readings(t)
    while gi < len(route) and math.hypot(route[gi][0] - x, route[gi][1] - y) < 0.01:
        gi += 1
    if gi == len(route):
        break
    goal = route[gi]
    dx, dy = goal[0] - x, goal[1] - y
    d = math.hypot(dx, dy)
    turn = wrap(math.atan2(dy, dx) - th)
    if abs(turn) > 0.05:  # turn in place at the corner, 1 rad/s
        dth, step = max(-0.1, min(0.1, turn)), 0.0
    else:
        dth, step = turn, min(a.speed * dt, d)
    th = wrap(th + dth)
    x, y = x + step * math.cos(th), y + step * math.sin(th)
    L = step + 0.1 * abs(dth)
    ns = step + rng.gauss(0, 0.0186 * math.sqrt(L))
    nth = dth + rng.gauss(0, 0.0093 * math.sqrt(L))
    oth += nth
    ox, oy = ox + ns * math.cos(oth), oy + ns * math.sin(oth)
    t += dt

with open(a.out + ".txt", "w") as f:
    f.write("\n".join(lines) + "\n")
with open(a.out + ".emitters.txt", "w") as f:
    for e in emitters:
        f.write(f"emitter {e[0]} {e[1]:.4f} {e[2]:.4f} {e[3]}\n")
with open(a.out + ".gt.tum", "w") as f:
    for T, px, py, pth in gt:
        f.write(f"{T:.4f} {px:.6f} {py:.6f} 0 0 0 {math.sin(pth/2):.9f} {math.cos(pth/2):.9f}\n")
print(f"{a.out}: {len(gt)} poses, {len(emitters)} emitters, failed {sorted(failed)}, moved {moved}")
