#!/usr/bin/env python3
"""Scenarios, summary and plot data of a campaign (tools/campaign; standard library only).

  campaign.py draw DIR --count N --seed S --end-time T --mesh-level L
      writes DIR/scenarios/case_NNN.json and DIR/parameters.csv
  campaign.py collect DIR
      writes DIR/summary.csv (and DIR/plot-data.txt for the plot) from DIR/runs/case_NNN/
  campaign.py check FILE...
      warns of what in each scenario lies outside the envelope (exit 1 if anything does)

Scenario i of seed S depends on (S, i), the mesh level and the end time only: the same
seed gives the same files, and a larger count adds cases without changing the first ones.
The envelope, the contact rule and the meshes are described in docs/validation.md,
"Operating envelope and campaigns".
"""
import argparse
import csv
import json
import math
import os
import random
import sys

# --- the envelope ----------------------------------------------------------------------
BOX_X = (-1.0, 1.0)        # Example 1's domain (engine/src/io/scenario_defaults.cpp)
BOX_Y = (-1.0, 0.5)
RADIUS_M = (0.1, 0.45)
SPEED_MPS = (0.0, 1.0)
SPEED_ANGLE_DEG = 45.0     # start velocity within this angle of straight down
MU_PA = (5e4, 3.2e6)       # log-uniform; lambda_s = 4 mu_s
DENSITY_RATIO = (0.5, 4.0)  # rho_s / rho_f
RHO_F_KGPM3 = (100.0, 1000.0)
NU_F_M2PS = (1e-3, 1e-2)
GRAVITY_MPS2 = (0.2, 2.0)  # downwards, on the solid only
CLEARANCE_M = 0.05         # the ball starts this far from every wall and open boundary
GEOMETRIES = ("floor", "ubox", "stairs")
STEP_X_M = (-0.4, 0.4)     # stairs: the riser's x
STEP_HEIGHT_M = (0.2, 0.5)  # stairs: the tread's height above the floor

# Contact rule: dist_0 = 1 cm; gamma_c scaled from the contact study's
# assets/scenarios/contact/d0_1e-2_g800.json (Example 1's ball: rho_s pi R^2 = 502.7 kg/m,
# g = 0.5 m/s^2, R = 0.4 m, gamma_c = 800 N/m, static rest distance 0.32 dist_0) so that
# every ball rests at the same fraction of dist_0: the force of P_c over the arc within
# dist_0 of a flat wall grows like gamma_c sqrt(R dist_0), and carries the weight
# rho_s pi R^2 |g| (gravity acts on the solid only).
CONTACT_DIST0_M = 1e-2
CONTACT_REF_GAMMA = 800.0
CONTACT_REF_WEIGHT = 1000.0 * math.pi * 0.4 ** 2 * 0.5
CONTACT_REF_RADIUS_M = 0.4

# Floors and treads: columns at most this many times as wide as the rows at the wall are
# thick (5 cm over 3.125 mm rows). Heavy balls landing on rows 7-10 cm wide (aspect 21-32)
# broke where the same landings on 5 cm columns did not (docs/solver.md, "Flat rows at a
# wall"); the engine's failure report names rows wider than this.
FLOOR_ASPECT_MAX = 16

# Base step per mesh level (level 1 = Example 1's 3.125 mm wall rows and k = 2e-3 s).
TIME_STEP_S = {0: 4e-3, 1: 2e-3, 2: 1e-3, 3: 5e-4, 4: 2.5e-4, 5: 1.25e-4}

PARAMETER_COLUMNS = [
    "seed", "index", "geometry", "radius_m", "center_x_m", "center_y_m", "vx_mps", "vy_mps",
    "speed_mps", "mu_s_pa", "lambda_s_pa", "density_ratio", "rho_s_kgpm3", "rho_f_kgpm3",
    "nu_f_m2ps", "gravity_mps2", "contact", "gamma_c", "dist0_m", "step_x_m", "step_y_m",
    "mesh_level", "time_step_s", "end_time_s"]
RESULT_COLUMNS = ["outcome", "reached_time_s", "steps", "unconverged_steps", "min_distance_m",
                  "max_mass_error", "wall_time_s", "stop_reason"]


def g4(x):
    """A number rounded to 4 significant digits (what the scenario file holds)."""
    return float("%.4g" % x)


def case_name(index):
    return "case_%03d" % index


# --- meshes ----------------------------------------------------------------------------
def piece(a, b, n, first=0.0, last=0.0, scale=1.0, origin=0.0):
    """An axis piece; with scale and origin in a mapped block's unit coordinates."""
    return {"from_m": g12((a - origin) / scale), "to_m": g12((b - origin) / scale), "patches": n,
            "first_m": g12(first / scale), "last_m": g12(last / scale)}


def g12(x):
    """A number rounded to 12 significant digits (mesh coordinates without float noise)."""
    return float("%.12g" % x)


def one_sided(a, b, fine, coarse):
    """Patches from size `fine` at a growing linearly towards `coarse` at b."""
    length = abs(b - a)
    n = max(2, round(2.0 * length / (fine + coarse)))
    return (a, b, n, fine, 2.0 * length / n - fine)


def uniform(a, b, coarse):
    return (a, b, max(1, round(abs(b - a) / coarse)), 0.0, 0.0)


def graded(a, b, fine_a, fine_b, fine, coarse):
    """Pieces from a to b, fine at the ends flagged (walls), as (a, b, n, first, last)."""
    if fine_a and fine_b:
        mid = 0.5 * (a + b)
        return [one_sided(a, mid, fine, coarse), flip(one_sided(b, mid, fine, coarse))]
    if fine_a:
        return [one_sided(a, b, fine, coarse)]
    if fine_b:
        return [flip(one_sided(b, a, fine, coarse))]
    return [uniform(a, b, coarse)]


def capped(a, b, fine_a, fine_b, fine, cap):
    """Pieces from a to b no wider than `cap`, growing from `fine` at the ends flagged (walls)
    by about 1.5 fine per patch: the columns over a floor."""
    n_grow = max(2, math.ceil((cap - fine) / (1.5 * fine)) + 1)
    grow = n_grow * 0.5 * (fine + cap)
    lo = a + grow if fine_a else a
    hi = b - grow if fine_b else b
    if hi - lo < cap:   # too short to reach cap: graded all the way
        return graded(a, b, fine_a, fine_b, fine, cap)
    specs = []
    if fine_a:
        specs.append((a, lo, n_grow, fine, cap))
    specs.append((lo, hi, math.ceil((hi - lo) / cap - 1e-9), 0.0, 0.0))
    if fine_b:
        specs.append((hi, b, n_grow, cap, fine))
    return specs


def flip(p):
    """The same patches described from the other end."""
    a, b, n, first, last = p
    return (b, a, n, last, first)


def pieces(specs, scale=1.0, origin=0.0):
    return [piece(a, b, n, f, l, scale, origin) for a, b, n, f, l in specs]


def mesh_for(geometry, level, step_x, step_y):
    """Blocks of the geometry's mesh and its refinements at this level (docs/validation.md)."""
    refinements = max(0, level - 1)
    coarse_level = level == 0
    fine = 0.00625 if coarse_level else 0.003125    # wall-normal patch size at a wall
    coarse = 0.2 if coarse_level else 0.1           # patch size far from the walls
    cap = FLOOR_ASPECT_MAX * fine                   # column width over a floor or tread
    x0, x1 = BOX_X
    y0, y1 = BOX_Y
    if geometry == "floor":
        # Example 1's rows (level 1) or half of them (level 0); its columns only under its
        # ball (2.5 cm), uniform here since a ball may land anywhere.
        n, top = (8, 0.00625) if coarse_level else (16, 0.003125)
        blocks = [{"x": pieces(capped(x0, x1, False, False, fine, cap)),
                   "y": [piece(y0, y1, 2 * n, top, 0.3 if coarse_level else 0.15)]}]
    elif geometry == "ubox":
        blocks = [{"x": pieces(capped(x0, x1, True, True, fine, cap)),
                   "y": pieces(graded(y0, y1, True, False, fine, coarse))}]
    else:
        # Stairs: tread at y = step_y for x < step_x, riser at x = step_x, floor right of it.
        # Block A above the tread; B (mapped) above the floor part and the tread's level,
        # its left side with A's thin rows, its right side with uniform ones (a fan block,
        # as the shipped stairs: no thin rows out in the fluid); C between the floor and
        # the tread's level.
        rows_up = graded(step_y, y1, True, False, fine, coarse)
        n_up = sum(p[2] for p in rows_up)
        cols_a = capped(x0, step_x, True, True, fine, cap)
        cols_r = capped(step_x, x1, True, True, fine, cap)
        width_r, height_up = x1 - step_x, y1 - step_y
        blocks = [
            {"x": pieces(cols_a), "y": pieces(rows_up)},
            {"x": pieces(cols_r, width_r, step_x), "y": pieces(rows_up, height_up, step_y),
             "mapped": True,
             "corners": [[g12(step_x), g12(step_y)], [x1, g12(step_y)], [x1, y1], [g12(step_x), y1]],
             "y_right": [piece(0.0, 1.0, n_up)]},
            {"x": pieces(cols_r), "y": pieces(graded(y0, step_y, True, False, fine, coarse))},
        ]
    return {"blocks": blocks, "refinements": refinements}


def walls_for(geometry, step_x, step_y):
    x0, x1 = BOX_X
    y0, y1 = BOX_Y
    if geometry == "floor":
        return [[[x0, y0], [x1, y0]]]
    if geometry == "ubox":
        return [[[x0, y1], [x0, y0]], [[x0, y0], [x1, y0]], [[x1, y0], [x1, y1]]]
    return [[[x0, y1], [x0, step_y]], [[x0, step_y], [step_x, step_y]],
            [[step_x, step_y], [step_x, y0]], [[step_x, y0], [x1, y0]], [[x1, y0], [x1, y1]]]


def segment_distance(p, a, b):
    ax, ay = a
    bx, by = b
    dx, dy = bx - ax, by - ay
    t = max(0.0, min(1.0, ((p[0] - ax) * dx + (p[1] - ay) * dy) / (dx * dx + dy * dy)))
    return math.hypot(p[0] - ax - t * dx, p[1] - ay - t * dy)


# --- drawing ---------------------------------------------------------------------------
def draw_case(seed, index, level, end_time):
    rng = random.Random(seed * 1000003 + index)
    geometry = GEOMETRIES[rng.randrange(len(GEOMETRIES))]
    radius = g4(rng.uniform(*RADIUS_M))
    step_x = step_y = None
    if geometry == "stairs":
        step_x = g4(rng.uniform(*STEP_X_M))
        step_y = g4(BOX_Y[0] + rng.uniform(*STEP_HEIGHT_M))
    walls = walls_for(geometry, step_x, step_y)
    # Start position: inside the box and CLEARANCE_M off every wall and open boundary.
    reach = radius + CLEARANCE_M
    for _ in range(100000):
        cx = g4(rng.uniform(BOX_X[0] + reach, BOX_X[1] - reach))
        cy = g4(rng.uniform(BOX_Y[0] + reach, BOX_Y[1] - reach))
        if all(segment_distance((cx, cy), a, b) >= reach for a, b in walls):
            break
    else:
        raise RuntimeError("no start position for case %d" % index)
    speed = rng.uniform(*SPEED_MPS)
    angle = math.radians(rng.uniform(-SPEED_ANGLE_DEG, SPEED_ANGLE_DEG))
    vx, vy = g4(speed * math.sin(angle)), g4(-speed * math.cos(angle))
    mu = g4(math.exp(rng.uniform(math.log(MU_PA[0]), math.log(MU_PA[1]))))
    ratio = rng.uniform(*DENSITY_RATIO)
    rho_f = g4(rng.uniform(*RHO_F_KGPM3))
    rho_s = g4(ratio * rho_f)
    nu_f = g4(rng.uniform(*NU_F_M2PS))
    gravity = g4(rng.uniform(*GRAVITY_MPS2))
    contact = rng.random() < 0.5
    gamma_c = dist0 = 0.0
    if contact:
        weight = rho_s * math.pi * radius ** 2 * gravity
        gamma_c = g4(CONTACT_REF_GAMMA * weight / CONTACT_REF_WEIGHT
                     * math.sqrt(CONTACT_REF_RADIUS_M / radius))
        dist0 = CONTACT_DIST0_M
    k = TIME_STEP_S[level]
    params = {
        "seed": seed, "index": index, "geometry": geometry, "radius_m": radius,
        "center_x_m": cx, "center_y_m": cy, "vx_mps": vx, "vy_mps": vy,
        "speed_mps": g4(math.hypot(vx, vy)), "mu_s_pa": mu, "lambda_s_pa": g12(4 * mu),
        "density_ratio": g4(rho_s / rho_f), "rho_s_kgpm3": rho_s, "rho_f_kgpm3": rho_f,
        "nu_f_m2ps": nu_f, "gravity_mps2": gravity, "contact": int(contact),
        "gamma_c": gamma_c, "dist0_m": dist0,
        "step_x_m": "" if step_x is None else step_x, "step_y_m": "" if step_y is None else step_y,
        "mesh_level": level, "time_step_s": k, "end_time_s": end_time,
    }
    # Physics, mesh, time step and end time only: every other numerics key is the default.
    scenario = {
        "name": "campaign_s%d_%03d" % (seed, index),
        "mesh": mesh_for(geometry, level, step_x, step_y),
        "walls": walls,
        "gravity_mps2": [0, -gravity],
        "body": {"center_m": [cx, cy], "radius_m": radius, "initial_velocity_mps": [vx, vy]},
        "fluid": {"density_kgpm3": rho_f, "viscosity_m2ps": nu_f},
        "solid": {"density_kgpm3": rho_s, "mu_pa": mu, "lambda_pa": g12(4 * mu)},
        "contact": {"gamma_c": gamma_c, "dist0_m": dist0},
        "numerics": {"time_step_s": k, "end_time_s": end_time},
    }
    return params, scenario


def scenario_text(scenario):
    """One top-level key per line, the mesh blocks one per line: stable and diffable."""
    lines = []
    for key, value in scenario.items():
        if key == "mesh":
            blocks = ",\n    ".join(json.dumps(b) for b in value["blocks"])
            text = '{"blocks": [\n    %s\n  ], "refinements": %d}' % (blocks, value["refinements"])
        else:
            text = json.dumps(value)
        lines.append('  "%s": %s' % (key, text))
    return "{\n" + ",\n".join(lines) + "\n}\n"


def write_csv(path, columns, rows, quoted=()):
    """CSV with the columns named in `quoted` always quoted (quotes doubled)."""
    tmp = path + ".tmp"
    with open(tmp, "w", newline="") as out:
        out.write(",".join(columns) + "\n")
        for row in rows:
            cells = []
            for c in columns:
                v = row.get(c, "")
                v = "" if v is None else ("%.6g" % v if isinstance(v, float) else str(v))
                if c in quoted or any(ch in v for ch in ',"\n'):
                    v = '"' + v.replace('"', '""').replace("\n", " ") + '"'
                cells.append(v)
            out.write(",".join(cells) + "\n")
    os.replace(tmp, path)


def command_draw(args):
    if args.mesh_level not in TIME_STEP_S:
        sys.exit("campaign: --mesh-level must be 0..%d" % max(TIME_STEP_S))
    sdir = os.path.join(args.dir, "scenarios")
    os.makedirs(sdir, exist_ok=True)
    rows = []
    for i in range(args.count):
        params, scenario = draw_case(args.seed, i, args.mesh_level, args.end_time)
        with open(os.path.join(sdir, case_name(i) + ".json"), "w") as out:
            out.write(scenario_text(scenario))
        rows.append(params)
    write_csv(os.path.join(args.dir, "parameters.csv"), PARAMETER_COLUMNS, rows)


# --- collecting ------------------------------------------------------------------------
def read_record(path):
    record = {}
    try:
        with open(path) as f:
            for line in f:
                if "=" in line:
                    k, v = line.rstrip("\n").split("=", 1)
                    record[k] = v
    except OSError:
        pass
    return record


def last_message(log):
    """The last line of a run's log that is not a progress line (why it died)."""
    try:
        with open(log, errors="replace") as f:
            lines = [l.strip() for l in f.read().replace("\r", "\n").split("\n") if l.strip()]
    except OSError:
        return ""
    return lines[-1][:300] if lines else ""


def max_mass_error(functionals):
    try:
        with open(functionals, newline="") as f:
            reader = csv.reader(f)
            header = next(reader)
            col = header.index("mass_error")
            best = None
            for row in reader:
                try:
                    v = abs(float(row[col]))
                except (ValueError, IndexError):
                    continue
                if not math.isnan(v) and (best is None or v > best):
                    best = v
            return best
    except (OSError, StopIteration, ValueError):
        return None


def fmt(x):
    return "" if x is None else "%.6g" % x


def left_domain(summary):
    """Whether the run's body reached an open boundary (the engine's left_domain event)."""
    events = summary.get("events") or []
    return any(isinstance(e, dict) and e.get("kind") == "left_domain" for e in events)


def result_of(run_dir):
    """The outcome columns of one run (RESULT_COLUMNS)."""
    record = read_record(os.path.join(run_dir, "campaign-run.txt"))
    summary = {}
    try:
        with open(os.path.join(run_dir, "summary.json")) as f:
            summary = json.load(f)
    except (OSError, ValueError):
        pass
    result = {c: "" for c in RESULT_COLUMNS}
    if not record:
        result["outcome"] = "not_run"
        return result
    rc = int(record.get("exit_code", "-1"))
    timed_out = record.get("timed_out") == "1"
    reason = summary.get("stop_reason", "") or ""
    reported = bool(summary.get("final")) and (bool(reason) or rc == 0)
    if timed_out:
        outcome = "stopped"
        reason = "timeout after %s s" % record.get("timeout_s", "?") + (": " + reason if reason else "")
    elif reported and reason and left_domain(summary):
        outcome = "left_domain"  # the body reached an open boundary: the domain ends there
    elif rc == 0 and reported:
        outcome = "finished" if not reason else "stopped"
    elif reported and reason:
        outcome = "stopped"     # e.g. interrupted by a signal, with its report
    else:
        outcome = "crashed"
        why = last_message(os.path.join(run_dir, "log.txt"))
        if rc > 128:
            why = "killed by signal %d" % (rc - 128) + (": " + why if why else "")
        else:
            why = "exit %d" % rc + (": " + why if why else "")
        reason = why
    min_d = summary.get("min_distance") or {}
    result.update({
        "outcome": outcome,
        "reached_time_s": fmt(summary.get("simulated_time_s")),
        "steps": summary.get("steps", ""),
        "unconverged_steps": summary.get("unconverged_steps", ""),
        "min_distance_m": fmt(min_d.get("distance_m") if isinstance(min_d, dict) else None),
        "max_mass_error": fmt(max_mass_error(os.path.join(run_dir, "functionals.csv"))),
        "wall_time_s": fmt(float(record["wall_s"])) if record.get("wall_s") else "",
        "stop_reason": reason,
    })
    return result


OUTCOME_CODE = {"finished": 0, "stopped": 1, "crashed": 2, "not_run": 3, "left_domain": 4}
GEOMETRY_CODE = {g: i for i, g in enumerate(GEOMETRIES)}


def command_collect(args):
    with open(os.path.join(args.dir, "parameters.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    for row in rows:
        row.update(result_of(os.path.join(args.dir, "runs", case_name(int(row["index"])))))
    write_csv(os.path.join(args.dir, "summary.csv"), PARAMETER_COLUMNS + RESULT_COLUMNS, rows,
              quoted=("stop_reason",))
    # Plot data: numeric columns, categories as numbers with a small deterministic jitter.
    with open(os.path.join(args.dir, "plot-data.txt"), "w") as out:
        out.write("# outcome radius mu_s ratio gravity speed contact_j geometry_j rho_f nu_f"
                  " reached_fraction index\n")
        for row in rows:
            i = int(row["index"])
            jitter = ((i * 0.618034) % 1.0 - 0.5) * 0.5
            reached = float(row["reached_time_s"] or 0) / float(row["end_time_s"])
            out.write("%d %s %s %s %s %s %.4f %.4f %s %s %.4f %d\n" % (
                OUTCOME_CODE[row["outcome"]], row["radius_m"], row["mu_s_pa"], row["density_ratio"],
                row["gravity_mps2"], row["speed_mps"], int(row["contact"]) + jitter,
                GEOMETRY_CODE[row["geometry"]] + jitter, row["rho_f_kgpm3"], row["nu_f_m2ps"],
                reached, i))
    counts = {}
    for row in rows:
        counts[row["outcome"]] = counts.get(row["outcome"], 0) + 1
    print("outcomes: " + ", ".join("%s %d" % kv for kv in sorted(counts.items())))


# --- checking a scenario against the envelope ------------------------------------------
def mesh_bounds(mesh):
    xs, ys = [], []
    for block in mesh.get("blocks", []):
        if block.get("mapped"):
            for x, y in block.get("corners", []):
                xs.append(x)
                ys.append(y)
        else:
            for p in block.get("x", []):
                xs += [p["from_m"], p["to_m"]]
            for p in block.get("y", []):
                ys += [p["from_m"], p["to_m"]]
    return (min(xs), max(xs), min(ys), max(ys)) if xs and ys else None


def envelope_problems(scenario):
    """What of a scenario lies outside the envelope (an empty list: nothing)."""
    problems = []
    body = scenario.get("body", {})
    solid = scenario.get("solid", {})
    fluid = scenario.get("fluid", {})
    radius = body.get("radius_m", 0.4)
    mu = solid.get("mu_pa", 2e5)
    lam = solid.get("lambda_pa", 8e5)
    rho_s = solid.get("density_kgpm3", 1000.0)
    rho_f = fluid.get("density_kgpm3", 1000.0)
    nu_f = fluid.get("viscosity_m2ps", 1e-3)
    gx, gy = scenario.get("gravity_mps2", [0.0, -0.5])
    vx, vy = body.get("initial_velocity_mps", [0.0, 0.0])
    cx, cy = body.get("center_m", [0.0, 0.0])

    # Ranges with a relative slack of 1e-3: drawn values are rounded to 4 digits.
    def within(name, value, lo, hi, unit=""):
        if not lo * (1 - 1e-3) <= value <= hi * (1 + 1e-3):
            problems.append("%s = %g%s is outside [%g, %g]" % (name, value, unit, lo, hi))

    if scenario.get("bodies"):
        problems.append("%d bodies: the envelope has one body" % len(scenario["bodies"]))
    if scenario.get("method", "fsi") != "fsi":
        problems.append('method "%s": the envelope is that of the default numerics ("fsi")'
                        % scenario.get("method"))
    other = sorted(set(scenario.get("numerics", {})) - {"time_step_s", "end_time_s"})
    if other:
        problems.append("numerics keys other than the step and the end time: " + ", ".join(other))
    within("radius", radius, *RADIUS_M, unit=" m")
    within("mu_s", mu, *MU_PA, unit=" Pa")
    if abs(lam - 4 * mu) > 1e-6 * 4 * mu:
        problems.append("lambda_s = %g Pa is not 4 mu_s = %g Pa" % (lam, 4 * mu))
    within("rho_s / rho_f", rho_s / rho_f, *DENSITY_RATIO)
    within("rho_f", rho_f, *RHO_F_KGPM3, unit=" kg/m^3")
    within("nu_f", nu_f, *NU_F_M2PS, unit=" m^2/s")
    within("|gravity|", math.hypot(gx, gy), *GRAVITY_MPS2, unit=" m/s^2")
    if abs(gx) > 1e-12 or gy >= 0:
        problems.append("gravity [%g, %g] does not point straight down" % (gx, gy))
    speed = math.hypot(vx, vy)
    within("start speed", speed, *SPEED_MPS, unit=" m/s")
    if speed > 0 and -vy < speed * math.cos(math.radians(SPEED_ANGLE_DEG)) - 1e-12:
        problems.append("start velocity [%g, %g] is more than %g degrees from straight down"
                        % (vx, vy, SPEED_ANGLE_DEG))
    bounds = mesh_bounds(scenario.get("mesh", {"blocks": [{"x": [{"from_m": -1, "to_m": 1}],
                                                           "y": [{"from_m": -1, "to_m": 0.5}]}]}))
    if bounds:
        x0, x1, y0, y1 = bounds
        if x0 < BOX_X[0] - 1e-9 or x1 > BOX_X[1] + 1e-9 or y0 < BOX_Y[0] - 1e-9 or y1 > BOX_Y[1] + 1e-9:
            problems.append("the domain [%g, %g] x [%g, %g] m is larger than Example 1's box" % bounds)
        reach = radius + CLEARANCE_M
        if not (x0 + reach <= cx + 1e-9 and cx <= x1 - reach + 1e-9 and y0 + reach <= cy + 1e-9
                and cy <= y1 - reach + 1e-9):
            problems.append("the ball starts closer than %g m to the domain's boundary" % CLEARANCE_M)
    walls = scenario.get("walls", [[[-1, -1], [1, -1]]])
    if any(segment_distance((cx, cy), a, b) < radius + CLEARANCE_M - 1e-9 for a, b in walls):
        problems.append("the ball starts closer than %g m to a wall" % CLEARANCE_M)
    return problems


def command_check(args):
    bad = 0
    for path in args.files:
        try:
            with open(path) as f:
                scenario = json.load(f)
        except (OSError, ValueError) as e:
            print("%s: cannot read: %s" % (path, e), file=sys.stderr)
            sys.exit(2)
        problems = envelope_problems(scenario)
        for p in problems:
            print("%s: warning: outside the envelope: %s" % (path, p))
        if not problems:
            print("%s: inside the envelope" % path)
        bad |= bool(problems)
    sys.exit(1 if bad else 0)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    d = sub.add_parser("draw")
    d.add_argument("dir")
    d.add_argument("--count", type=int, required=True)
    d.add_argument("--seed", type=int, required=True)
    d.add_argument("--end-time", type=float, required=True)
    d.add_argument("--mesh-level", type=int, required=True)
    c = sub.add_parser("collect")
    c.add_argument("dir")
    k = sub.add_parser("check")
    k.add_argument("files", nargs="+")
    args = parser.parse_args()
    {"draw": command_draw, "collect": command_collect, "check": command_check}[args.command](args)


if __name__ == "__main__":
    main()
