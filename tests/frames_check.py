#!/usr/bin/env python3
"""Read bonkers' trajectories back with the real readers and check them.

    python3 tests/frames_check.py OUTDIR

OUTDIR holds one folder per descriptor of tests/frames/, each with `gsd/`
(`study run tests/frames/<name>.toml --out OUTDIR/<name>/gsd`) and `xyz/`
(the same with `--quick`, whose only change is the format): the same run,
written twice. For each it checks, frame by frame:

- the GSD file (`gsd.hoomd`): frame count and times, box and dimensions,
  N, types (the species names), typeid, diameter and mass against the
  descriptor; positions inside HOOMD's [-L/2, L/2), image flags only on
  periodic axes;
- the XYZ file (`ase.io.read(..., index=':')`): the same frames, times, cell,
  pbc and types, positions equal to the GSD's plus L/2 bit for bit (the
  XYZ is in the box's own [0, L)), velocities equal;
- known values: the explicit start of a scene is frame 0, and the measured
  run's `positions` (and in 1D `velocities`) series equal the frames at
  every sample time: the trajectory is the run the tables describe;
- image flags: the unwrapped path (position + image * L) moves between
  frames by no more than the fastest speed the energy allows, flags change
  by at most one per frame, and some particle does cross;
- g(r): freud's RDF of the frames of a periodic 2D or 3D run against the
  run's own `pair_distance` histogram (histograms.parquet), bin by bin
  within 4 sigma of the counts' Poisson error.
"""

import json
import math
import pathlib
import sys

import ase.io
import freud
import gsd.hoomd
import numpy as np
import pandas as pd

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print(f"  FAIL: {what}")
    return ok


def scene_of(out):
    d = json.loads((out / "manifest.json").read_text())["descriptor"]
    s, run = d["scene"], d["run"]
    dim = s.get("dimension") or 1
    boundary = s.get("boundary") or ["walls"] * dim
    species = [sp["name"] for sp in s["species"]]
    return d, dim, np.array(s["box"], dtype=float), [b == "periodic" for b in boundary], species


def expected_box(dim, box):
    if dim == 1:
        return [box[0], 1.0, 0.0, 0, 0, 0], 2
    if dim == 2:
        return [box[0], box[1], 0.0, 0, 0, 0], 2
    return [box[0], box[1], box[2], 0, 0, 0], 3


def one(name, folder):
    print(f"{name}:")
    gdir, xdir = folder / "gsd", folder / "xyz"
    d, dim, box, periodic, species = scene_of(gdir)
    t = d["observe"]["trajectory"]
    every, run = t["every"], d["run"]
    length = run.get("equilibrate", 0.0) + run["duration"]
    frames = math.floor(length / every) + 1
    pad = np.zeros(3)
    pad[:dim] = box
    half = 0.5 * pad

    traj = gsd.hoomd.open(gdir / "trajectory-0.gsd")
    xyz = ase.io.read(xdir / "trajectory-0.xyz", index=":")
    check(len(traj) == frames, f"{name}: {len(traj)} GSD frames, expected {frames}")
    check(len(xyz) == frames, f"{name}: {len(xyz)} XYZ frames, expected {frames}")
    radius = {sp["name"]: sp.get("radius", 0.5) for sp in d["scene"]["species"]}
    mass = {sp["name"]: sp.get("mass", 1.0) for sp in d["scene"]["species"]}
    count = {sp["name"]: sp["count"] for sp in d["scene"]["species"]}
    want_box, want_dim = expected_box(dim, box)

    series = pd.read_parquet(gdir / "series.parquet")
    by_name = {k: g.set_index("t")["value"] for k, g in series.groupby("observable")}
    explicit = d["scene"].get("placement", {}) or {}
    start_v = d["scene"].get("velocities", {}) or {}

    path, prev_image, matched = [], None, 0
    for k, (f, a) in enumerate(zip(traj, xyz)):
        time = float(f.log["time"][0])
        n = f.particles.N
        tag = f"{name} frame {k}"
        check(f.configuration.step == k, f"{tag}: step {f.configuration.step}")
        check(abs(time - k * every) <= 1e-9 * (1 + length), f"{tag}: time {time}")
        check(f.configuration.dimensions == want_dim, f"{tag}: dimensions")
        check(np.array_equal(f.configuration.box, want_box), f"{tag}: box {f.configuration.box}")
        check(f.particles.types == species, f"{tag}: types {f.particles.types}")
        check(n == sum(count.values()), f"{tag}: N = {n}")
        names = np.array(species)[f.particles.typeid]
        for s in species:
            check(np.sum(names == s) == count[s], f"{tag}: count of {s}")
        check(np.array_equal(f.particles.diameter, [2 * radius[s] for s in names]), f"{tag}: diameter")
        check(np.array_equal(f.particles.mass, [mass[s] for s in names]), f"{tag}: mass")
        p, v, img = f.particles.position, f.particles.velocity, f.particles.image
        check(np.all(p[:, dim:] == 0) and np.all(v[:, dim:] == 0), f"{tag}: padded axes not 0")
        inside = (p[:, :dim] >= -half[:dim]) & (p[:, :dim] < half[:dim])
        check(inside.all(), f"{tag}: a position outside [-L/2, L/2)")
        for ax in range(3):
            if ax >= dim or not periodic[ax]:
                check(np.all(img[:, ax] == 0), f"{tag}: image flags on a non-periodic axis {ax}")
        # The XYZ: the same frame in the box's own coordinates.
        check(a.info["Time"] == time, f"{tag}: XYZ time {a.info['Time']} vs {time}")
        check(np.array_equal(a.cell[:], np.diag(pad)), f"{tag}: XYZ cell {a.cell[:]}")
        check(list(a.pbc) == [ax < dim and periodic[ax] for ax in range(3)], f"{tag}: pbc {a.pbc}")
        check(list(a.arrays["type"]) == [s.replace(" ", "_") for s in names], f"{tag}: XYZ types")
        x = a.get_positions()
        shifted = x.copy()
        shifted[:, :dim] -= half[:dim]
        check(np.array_equal(shifted, p), f"{tag}: XYZ positions - L/2 differ from the GSD's")
        check(np.array_equal(a.arrays["vel"], v), f"{tag}: XYZ velocities differ from the GSD's")
        # The measured run's own samples at this time.
        if "x.0" in by_name and time in by_name["x.0"].index:
            matched += 1
            xs = np.array([by_name[f"x.{i}"][time] for i in range(n)])
            check(np.array_equal(xs, x[:, 0]), f"{tag}: positions series differs from the frame")
            if "v.0" in by_name:
                vs = np.array([by_name[f"v.{i}"][time] for i in range(n)])
                check(np.array_equal(vs, v[:, 0]), f"{tag}: velocities series differs")
        if k == 0 and explicit.get("kind") == "explicit":
            want = np.zeros((n, 3))
            want[:, :dim] = explicit["positions"]
            check(np.array_equal(x, want), f"{tag}: frame 0 is not the explicit start")
        if k == 0 and start_v.get("kind") == "explicit":
            want = np.zeros((n, 3))
            want[:, :dim] = start_v["velocities"]
            check(np.array_equal(v, want), f"{tag}: frame 0 velocities are not the explicit ones")
        if prev_image is not None:
            check(np.abs(img - prev_image).max(initial=0) <= 1, f"{tag}: a flag jumps by more than 1")
        prev_image = img.copy()
        path.append(p + img * pad)
    check(matched == frames, f"{name}: {matched} of {frames} frames matched a series sample")

    # Image flags: the unwrapped path is continuous.
    masses = traj[0].particles.mass
    energy = 0.5 * np.sum(masses[:, None] * traj[0].particles.velocity ** 2)
    fastest = math.sqrt(2 * energy / masses.min())
    steps = np.abs(np.diff(np.array(path), axis=0))
    worst = steps.max(initial=0) / (fastest * every)
    check(worst <= 1 + 1e-9, f"{name}: an unwrapped step is {worst:.3f} of the largest possible")
    crossings = np.abs(np.diff(np.array([f.particles.image for f in traj]), axis=0)).sum()
    if any(periodic):
        check(crossings > 0, f"{name}: no particle crossed the box")
    print(f"  {frames} frames of {traj[0].particles.N} particles; GSD and XYZ equal; "
          f"{matched} frames equal to the run's samples; {crossings} box crossings; "
          f"largest unwrapped step {worst:.3f} of the energy's bound")

    if dim >= 2 and all(periodic[:dim]) and (gdir / "histograms.parquet").exists():
        rdf_check(name, gdir, traj, dim)


def rdf_check(name, gdir, traj, dim):
    h = pd.read_parquet(gdir / "histograms.parquet")
    h = h[h.observable == "pair_distance"].sort_values("lo")
    width = float(h.hi.iloc[0] - h.lo.iloc[0])
    bins = len(h)
    L = traj[0].configuration.box[:dim]
    while bins * width >= 0.5 * L.min():
        bins -= 1
    rdf = freud.density.RDF(bins=bins, r_max=bins * width)
    for f in traj:
        b = freud.box.Box.from_box(f.configuration.box, dimensions=dim)
        rdf.compute(system=(b, f.particles.position), reset=False)
    frames = len(traj)
    # The run's own samples (its series' times); the frames may be fewer.
    series = pd.read_parquet(gdir / "series.parquet")
    samples = series[series.observable == "x.0"].t.nunique()
    # freud counts each pair from both ends; pair_distance is pairs per sample.
    theirs = rdf.bin_counts / 2 / frames
    ours = h["count"].to_numpy()[:bins]
    # Poisson errors of the two means (the frames are among the samples, so
    # the difference varies less than this).
    sigma = np.sqrt(ours / samples + theirs / frames)
    z = np.where(sigma > 0, (theirs - ours) / np.where(sigma > 0, sigma, 1), 0)
    worst = np.abs(z).max()
    check(worst < 4, f"{name}: freud's pair counts differ from pair_distance by {worst:.1f} sigma")
    r = rdf.bin_centers
    peak = r[np.argmax(rdf.rdf)]
    print(f"  g(r): {bins} bins of {width} up to {bins * width:.2f}, {frames} frames against {samples} samples; "
          f"largest |freud - pair_distance| {worst:.2f} sigma; freud's g peaks at r = {peak:.2f}")


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    root = pathlib.Path(sys.argv[1])
    folders = sorted(p for p in root.iterdir() if (p / "gsd").is_dir() and (p / "xyz").is_dir())
    if not folders:
        sys.exit(f"no <name>/gsd and <name>/xyz folders in {root}")
    for folder in folders:
        one(folder.name, folder)
    if failures:
        sys.exit(f"{len(failures)} checks failed")
    print(f"frames_check: {len(folders)} trajectories read back by gsd, ase and freud: ok")


if __name__ == "__main__":
    main()
