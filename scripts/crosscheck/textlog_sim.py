#!/usr/bin/env python3
"""An RFID-floor simulator independent of rfir-sim, written from the text-log
format alone (docs/textlog.md), as an outside user would: an omnidirectional
robot, readers of any layout, a tag grid, odometry with a random-walk error,
optional asynchronous reader polling, epoch timestamps and a kidnapping.
Writes NAME.txt (textlog 1), NAME.gt.tum and NAME.gt_map.txt. Standard
library only; see scripts/crosscheck.sh."""
import argparse, math, random

import simargs

ap = argparse.ArgumentParser()
ap.add_argument("--out", required=True, help="output prefix")
ap.add_argument("--layout", default="ring8_60",
                choices=["ring8_60", "ring8_300", "grid4_rect", "line3", "single"])
ap.add_argument("--density", type=float, default=16, help="tags per m^2 (square grid)")
ap.add_argument("--path", default="loop", choices=["loop", "random", "lawn"])
ap.add_argument("--area", default="3x3", help="floor W x H, m")
ap.add_argument("--duration", type=float, default=120, help="s")
ap.add_argument("--speed", type=float, default=0.2, help="m/s")
ap.add_argument("--omega", type=float, default=0.0, help="spin while moving, rad/s")
ap.add_argument("--sigma_xy", type=float, default=0.01, help="odometry, m per sqrt(m)")
ap.add_argument("--sigma_phi", type=float, default=0.005, help="odometry, rad per sqrt(m)")
ap.add_argument("--async", dest="async_", action="store_true",
                help="odometry at --odom-hz, each reader polled at its own time")
ap.add_argument("--odom-hz", type=float, default=50.0,
                help="odometry rate with --async (default 50)")
ap.add_argument("--rr-hz", type=float, default=0.0,
                help="readers polled round robin, each at this rate (with --async; "
                     "0: every reader once per odometry interval)")
ap.add_argument("--lag", type=float, default=0.0,
                help="odometry latency, s: a record stamped T tells the pose of T - lag")
ap.add_argument("--scale", type=float, default=1.0, help="odometry translation scale")
ap.add_argument("--drift", type=float, default=0.0, help="odometry heading drift, rad/m")
ap.add_argument("--slips", type=int, default=0,
                help="wheel slips: odometry jumps 0.1-0.3 m forward that the robot did not make")
ap.add_argument("--dead", default="", help="reader index,from,to (s): it reads nothing then")
ap.add_argument("--ghost", type=float, default=0.0,
                help="per poll: the reader also reports a real tag 0.2-0.6 m from it")
ap.add_argument("--t0", type=float, default=0.0, help="first timestamp, s")
ap.add_argument("--kidnap", type=float, default=-1,
                help="at this time the robot is carried 2 s (no records) to a random spot")
ap.add_argument("--kidnap-turn", type=float, default=0.0,
                help="with --kidnap: the robot is also turned by up to this many rad")
ap.add_argument("--kidnap-dist", type=float, default=0.0,
                help="with --kidnap: put down this far (m) from where it was picked up "
                     "(0: anywhere on the floor)")
ap.add_argument("--miss", type=float, default=0.0,
                help="per read: the probability that a tag in a reader's square is not read")
ap.add_argument("--seed", type=int, default=1)
ap.add_argument("--start", default="0.5,0.5,0", help="start pose x,y,phi (the log's start record)")
a = ap.parse_args()
rng = random.Random(a.seed)
W, H = simargs.area(ap, a.area, "3x3")
simargs.positive(ap, a, ("density", "duration", "speed", "odom_hz"))
if W <= 1.5 or H <= 1.5:
    ap.error("--area: each side must exceed 1.5 m (the paths keep 0.5 m margins)")
if a.odom_hz != 50.0 and not a.async_:
    ap.error("--odom-hz needs --async")
if a.rr_hz < 0 or a.lag < 0 or a.ghost < 0 or a.slips < 0:
    ap.error("--rr-hz, --lag, --ghost and --slips must not be negative")
if a.rr_hz and not a.async_:
    ap.error("--rr-hz needs --async")
if a.lag and not a.rr_hz:
    ap.error("--lag needs --rr-hz (the lines are then sorted by time)")
dead = None
if a.dead:
    try:
        dead = tuple(float(v) for v in a.dead.split(","))
        assert len(dead) == 3
    except (ValueError, AssertionError):
        ap.error(f"--dead must be reader,from,to, not '{a.dead}'")
slip_times = sorted(rng.uniform(0.1, 0.9) * a.duration for _ in range(a.slips))

def layout(name):
    if name == "ring8_60":
        return [(f"R{i}", 0.15 * math.cos(i * math.pi / 4), 0.15 * math.sin(i * math.pi / 4), 0.03, 0.03) for i in range(8)]
    if name == "ring8_300":
        return [(f"R{i}", 0.4 * math.cos(i * math.pi / 4), 0.4 * math.sin(i * math.pi / 4), 0.15, 0.15) for i in range(8)]
    if name == "grid4_rect":
        return [(f"ant{i}", sx * 0.12, sy * 0.08, 0.06, 0.025) for i, (sx, sy) in enumerate([(1, 1), (1, -1), (-1, 1), (-1, -1)])]
    if name == "line3":
        return [(f"{i}", 0.1, (i - 1) * 0.1, 0.04, 0.04) for i in range(3)]
    if name == "single":
        return [("reader", 0.0, 0.0, 0.05, 0.05)]
    raise AssertionError(name)  # argparse's choices

readers = layout(a.layout)
if dead and not (dead[0] == int(dead[0]) and 0 <= int(dead[0]) < len(readers)):
    ap.error(f"--dead: reader index {dead[0]:g} is not one of the layout's 0-{len(readers) - 1}")
pitch = 1 / math.sqrt(a.density)
tags = []
n = 0
y = pitch / 2
while y < H:
    x = pitch / 2
    while x < W:
        tags.append((f"E0040150{n:08X}", x, y))
        n += 1
        x += pitch
    y += pitch
cell = 0.5
grid = {}
for t in tags:
    grid.setdefault((int(t[1] / cell), int(t[2] / cell)), []).append(t)

def waypoints():
    m = 0.5
    if a.path == "loop":
        pts = [(m, m), (W - m, m), (W - m, H - m), (m, H - m)]
        while True:
            for p in pts[1:] + pts[:1]:
                yield p
    elif a.path == "lawn":
        k = 0
        while True:
            y = m + (k % int((H - 2 * m) / 0.5 + 1)) * 0.5
            yield (W - m, y) if k % 2 == 0 else (m, y)
            k += 1
            yield (W - m, y) if k % 2 == 0 else (m, y)
    else:
        while True:
            yield (rng.uniform(m, W - m), rng.uniform(m, H - m))

x, y, th = (float(v) for v in a.start.split(","))
ox, oy, oth = 0.0, 0.0, 0.0  # odometry frame = start pose
dt_odom = 1.0 / a.odom_hz if a.async_ else 0.1
lines = ["format textlog 1", f"# foreign simulator seed {a.seed} layout {a.layout}"]
for r in readers:
    lines.append(f"reader {r[0]} {r[1]:.6f} {r[2]:.6f} {r[3]} {r[4]}")
lines.append(f"start {x} {y} {th}")
gt, wp = [], waypoints()
goal = next(wp)
t = 0.0
kid_done = False
next_poll, poll_k, polls = 0.01, 0, []  # --rr-hz: polls sorted into the odometry by time

def wrap(v):
    while v > math.pi: v -= 2 * math.pi
    while v <= -math.pi: v += 2 * math.pi
    return v

def ghost(rx, ry):
    """A real tag 0.2-0.6 m from the reader's centre, or None."""
    for _ in range(20):
        d, b = rng.uniform(0.2, 0.6), rng.uniform(-math.pi, math.pi)
        cand = grid.get((int((rx + d * math.cos(b)) / cell), int((ry + d * math.sin(b)) / cell)), [])
        near = [t for t in cand if 0.2 <= math.hypot(t[1] - rx, t[2] - ry) <= 0.6]
        if near:
            return rng.choice(near)[0]
    return None

def reads(px, py, pth, r, T=0.0):
    c, s = math.cos(pth), math.sin(pth)
    rx, ry = px + c * r[1] - s * r[2], py + s * r[1] + c * r[2]
    if dead and readers.index(r) == int(dead[0]) and dead[1] <= T <= dead[2]:
        return []
    out = []
    g = ghost(rx, ry) if a.ghost and rng.random() < a.ghost else None
    for i in range(int(rx / cell) - 1, int(rx / cell) + 2):
        for j in range(int(ry / cell) - 1, int(ry / cell) + 2):
            for tg in grid.get((i, j), []):
                dx, dy = tg[1] - rx, tg[2] - ry
                ex, ey = c * dx + s * dy, -s * dx + c * dy
                if abs(ex) < r[3] and abs(ey) < r[4]:
                    if not (a.miss and rng.random() < a.miss):
                        out.append(tg[0])
    if g and g not in out:
        out.append(g)
    return out

def fmt(v):
    return f"{v:.6f}"

while t <= a.duration + 1e-9:
    T = a.t0 + t
    gt.append((T, x, y, th))
    lines.append(f"odom {T + a.lag:.4f} {fmt(ox)} {fmt(oy)} {fmt(wrap(oth))}")
    if not a.async_:
        for r in readers:
            ids = reads(x, y, th, r, t)
            lines.append(f"rfid {T:.4f} {r[0]} " + " ".join(ids))
    # move for dt_odom: omni robot heads to the goal in the world frame
    dx, dy = goal[0] - x, goal[1] - y
    d = math.hypot(dx, dy)
    if d < 0.05:
        goal = next(wp)
        dx, dy = goal[0] - x, goal[1] - y
        d = math.hypot(dx, dy)
    stepl = min(a.speed * dt_odom, d)
    wx, wy = dx / d * stepl, dy / d * stepl
    c, s = math.cos(th), math.sin(th)
    bx, by = c * wx + s * wy, -s * wx + c * wy  # body-frame increment
    bth = a.omega * dt_odom
    if a.async_ and a.rr_hz:
        # one reader after the other, each at rr_hz, 2 ms of jitter
        period = 1.0 / (a.rr_hz * len(readers))
        while next_poll < t + dt_odom:
            f = (next_poll - t) / dt_odom
            tk = next_poll + rng.uniform(-0.002, 0.002)
            r = readers[poll_k % len(readers)]
            ids = reads(x + wx * f, y + wy * f, th + bth * f, r, next_poll)
            polls.append((a.t0 + tk, f"rfid {a.t0 + tk:.4f} {r[0]} " + " ".join(ids)))
            poll_k += 1
            next_poll += period
    elif a.async_:
        # readers polled round robin between odom samples, each at its own t
        for k, r in enumerate(readers):
            tk = t + dt_odom * (k + 0.5) / len(readers)
            f = (k + 0.5) / len(readers)
            px, py, pth = x + wx * f, y + wy * f, th + bth * f
            lines.append(f"rfid {a.t0 + tk:.4f} {r[0]} " + " ".join(reads(px, py, pth, r)))
    x, y, th = x + wx, y + wy, wrap(th + bth)
    # odometry: true increment plus random-walk noise
    L = math.hypot(bx, by) + 0.1 * abs(bth)
    nx = bx + rng.gauss(0, a.sigma_xy * math.sqrt(L))
    ny = by + rng.gauss(0, a.sigma_xy * math.sqrt(L))
    nth = bth + rng.gauss(0, a.sigma_phi * math.sqrt(L))
    nx, ny, nth = nx * a.scale, ny * a.scale, nth + a.drift * math.hypot(bx, by)
    while slip_times and slip_times[0] < t + dt_odom:
        slip_times.pop(0)
        nx += rng.uniform(0.1, 0.3)
    co, so = math.cos(oth), math.sin(oth)
    ox, oy, oth = ox + co * nx - so * ny, oy + so * nx + co * ny, oth + nth
    t += dt_odom
    if a.kidnap >= 0 and not kid_done and t >= a.kidnap:
        kid_done = True
        # carried for 2 s: no odometry, no reads; put down elsewhere
        t += 2.0
        while a.rr_hz and next_poll < t:  # no polls while carried
            next_poll += 1.0 / (a.rr_hz * len(readers))
        if a.kidnap_dist > 0:
            for _ in range(100):  # a direction that stays on the floor
                b = rng.uniform(-math.pi, math.pi)
                nx, ny = x + a.kidnap_dist * math.cos(b), y + a.kidnap_dist * math.sin(b)
                if 0.5 <= nx <= W - 0.5 and 0.5 <= ny <= H - 0.5:
                    break
            x, y = nx, ny
        else:
            x, y = rng.uniform(0.5, W - 0.5), rng.uniform(0.5, H - 0.5)
        if a.kidnap_turn > 0:
            th = wrap(th + rng.uniform(-a.kidnap_turn, a.kidnap_turn))
        goal = next(wp)

if polls:  # the odometry lines (stamped + lag) and the polls in time order
    head = [l for l in lines if not l.startswith("odom ")]
    timed = [(float(l.split()[1]), l) for l in lines if l.startswith("odom ")] + polls
    timed.sort(key=lambda p: p[0])
    lines = head + [l for _, l in timed]
with open(a.out + ".txt", "w") as f:
    f.write("\n".join(lines) + "\n")
with open(a.out + ".gt.tum", "w") as f:
    for T, px, py, pth in gt:
        f.write(f"{T:.4f} {px:.6f} {py:.6f} 0 0 0 {math.sin(pth/2):.9f} {math.cos(pth/2):.9f}\n")
with open(a.out + ".gt_map.txt", "w") as f:
    for tg in tags:
        f.write(f"tag {tg[0]} {tg[1]:.6f} {tg[2]:.6f}\n")
print(f"{a.out}: {len(gt)} poses, {len(tags)} tags, {len(lines)} lines")
