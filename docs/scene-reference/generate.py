#!/usr/bin/env python3
"""Writes docs/scene-reference.md from the scene parser's own catalogue of keys:

    build/grainlab scene-keys --json | python3 docs/scene-reference/generate.py > docs/scene-reference.md

The kinds, defaults, ranges, choices and stage types come from the catalogue (what the parser
reads); the units and meanings below are the only hand-written part. A key the parser accepts
that has no meaning here is an error, so the reference cannot silently fall behind the parser
(the test docs_scene_reference runs this and compares the result with the committed file)."""
import json
import sys

# path -> (unit, meaning). "–" for a dimensionless number, "" where a unit does not apply.
MEANINGS = {
    "name": ("", "the scene's name, shown by the dashboard and the sweeps"),
    "seed": ("", "the random packing: the same scene and seed give the same bits"),
    "gravity": ("m/s²", "body acceleration (x, y); the paper's tests have none"),
    "material": ("", "the one contact material of the scene"),
    "material.density": ("kg/m³", "particle density (2D: mass per area per metre of thickness)"),
    "material.normal_stiffness": ("N/m", "k_n: normal contact spring, force per metre of thickness per metre of overlap"),
    "material.tangential_stiffness": ("N/m", "k_t: tangential contact spring"),
    "material.friction": ("–", "Coulomb friction coefficient μ between particles (a stage may override it)"),
    "material.restitution": ("–", "normal coefficient of restitution e of a binary collision; sets a viscous damping per pair"),
    "material.local_damping": ("–", "Cundall's non-viscous damping α (0: none)"),
    "material.rolling_friction": ("–", "rolling resistance μ_r of discs: the couple resisting relative rotation is at most μ_r R* f_n (0: none; discs and the dem engine only; docs/shape-fidelity.md)"),
    "material.rolling_stiffness_ratio": ("–", "β: the rolling spring is k_r = β k_t R*² per radian (R* = R_i R_j / (R_i + R_j))"),
    "material.rolling_damping": ("–", "η_r: the rolling damper's fraction of its critical value 2√(I_r k_r), off while the couple is at its cap"),
    "particles": ("", "explicit particles, besides any generated assembly"),
    "particles[].shape": ("", "disc, convex polygon, or clump (a rigid body of overlapping discs)"),
    "particles[].radius": ("m", "disc radius (discs)"),
    "particles[].vertices": ("m", "polygon corners [[x, y], ...] relative to `position` in the body frame, convex, 3-8 of them"),
    "particles[].position": ("m", "centre (disc) or reference point of `vertices` (polygon) or of `members` (clump)"),
    "particles[].members": ("", "a clump's discs, 1-64 of them, each overlapping another (one connected body); its mass and inertia are the union's, overlaps counted once"),
    "particles[].members[].position": ("m", "a member disc's centre relative to the particle's `position` in the body frame"),
    "particles[].members[].radius": ("m", "a member disc's radius"),
    "particles[].angle": ("rad", "initial orientation, counter-clockwise"),
    "particles[].velocity": ("m/s", "initial velocity (the prescribed one for kinematic particles)"),
    "particles[].spin": ("rad/s", "initial angular velocity, counter-clockwise"),
    "particles[].motion": ("", "dynamic (moved by forces), fixed, or kinematic (moves at its given velocity)"),
    "particles[].boundary": ("", "part of the loading boundary, not of the measured specimen"),
    "walls": ("", "static half-planes"),
    "walls[].point": ("m", "a point on the wall's surface"),
    "walls[].normal": ("–", "unit normal pointing into the free space; the solid is on the other side"),
    "assembly": ("", "a generated specimen (the paper's assemblies), placed at random without overlap, then numbered along space in rows, so that nearby particles have nearby indices (the ring's discs come last)"),
    "assembly.shape": ("", "equal discs, elongated convex polygons, or clumps of equal discs in a line"),
    "assembly.disc_radius": ("m", "radius of the discs (shape disc)"),
    "assembly.long_axes": ("m", "long-axis lengths of the polygon or clump size classes (shape elongated or clump); omitted: [0.0045, 0.005, 0.007], the paper's three sizes"),
    "assembly.count_fractions": ("–", "share of each size class by number, summing to 1; omitted: solved for the paper's grading"),
    "assembly.aspect_ratio": ("–", "polygons: long over short axis of the ellipse each is inscribed in; clumps: long axis over width (the discs' diameter), below `clump_discs`"),
    "assembly.clump_discs": ("", "equal discs per clump, centres evenly along the long axis, the outer ones touching its ends (shape clump)"),
    "assembly.vertices": ("", "corners per polygon"),
    "assembly.orientation": ("", "random long-axis orientations, or bedded at `bedding_angle_deg`"),
    "assembly.bedding_angle_deg": ("°", "the long axes' angle from the horizontal, counter-clockwise (orientation bedding)"),
    "assembly.specimen_diameter": ("m", "the consolidated specimen's target diameter"),
    "assembly.target_void_ratio": ("–", "the void ratio the particle count is sized for at that diameter"),
    "assembly.particle_count": ("", "fixes the particle count instead of deriving it from the two keys above"),
    "assembly.boundary_radius": ("m", "radius of the ring's boundary discs; 0: half the smallest particle width"),
    "boundary": ("", "the loading boundary around a generated assembly"),
    "boundary.type": ("", "membrane: a ring of kinematic boundary discs that the stages move; periodic: a deformable periodic cell, no boundary particles (docs/periodic-cell.md); none: no boundary"),
    "boundary.size": ("m", "periodic, explicit particles: the rectangular cell's [width, height] (an assembly sizes its own cell)"),
    "boundary.rate_cap": ("1/s", "periodic: the largest strain rate the cell's stress servos may command in biaxial and simple_shear stages"),
    "stages": ("", "the loading programme, run in order"),
    "stages[].type": ("", "what the stage does (README.md, \"Scene JSON\"; docs/loading-paths.md for rotation, cyclic, simple_shear)"),
    "stages[].name": ("", "the stage's label in series.csv's `stage` column and the charts"),
    "stages[].duration": ("s", "simulated time the stage runs (free) or the rotation lasts (rotation)"),
    "stages[].pressure": ("Pa", "compaction: stop at this mean stress; isotropic: target σ11 = σ22; biaxial, cyclic: σ11 held"),
    "stages[].strain_rate": ("1/s", "compaction, isotropic: the boundary's strain-rate scale (a cap for the servo); biaxial, cyclic: axial compression rate ε̇22"),
    "stages[].void_ratio": ("–", "compaction: stop once the void ratio inside the ring is this low"),
    "stages[].friction": ("–", "μ during this stage (compaction defaults to 0; the others keep material.friction unless given)"),
    "stages[].max_time": ("s", "the stage ends here even if its criterion is unmet (noted in summary.json); derived: twice the time its target strain or rotation takes"),
    "stages[].target_axial_strain": ("–", "biaxial: stop at this axial strain ε22"),
    "stages[].lateral": ("", "biaxial, cyclic: hold σ11 (constant_stress) or the area (constant_volume)"),
    "stages[].mean_stress": ("Pa", "rotation: the mean stress p held"),
    "stages[].deviatoric_strain_rate": ("1/s", "rotation: ε̇1 − ε̇3 of the imposed strain rate (the ring; refused in a periodic cell)"),
    "stages[].deviatoric_stress": ("Pa", "rotation in a periodic cell: q = (σ1 − σ2)/2 held while the stress axes turn (below mean_stress; docs/periodic-cell.md)"),
    "stages[].rotation_rate_deg_per_s": ("°/s", "rotation: how fast the strain-rate axes (a periodic cell: the stress axes) turn, counter-clockwise positive"),
    "stages[].total_rotation_deg": ("°", "rotation: how far they turn (give two of rate, total, duration)"),
    "stages[].initial_direction_deg": ("°", "rotation: the major compression direction θ_ε̇ at the start (a periodic cell: the major stress direction θσ; 90°: vertical)"),
    "stages[].strain_amplitude": ("–", "cyclic: reverse at axial strain ±amplitude"),
    "stages[].q_over_p_limits": ("–", "cyclic: [lower, upper] of (σ22 − σ11)/(σ22 + σ11) at which to reverse, instead of an amplitude"),
    "stages[].cycles": ("", "cyclic: number of compression-extension cycles"),
    "stages[].shear_rate": ("1/s", "simple_shear: shear rate γ̇"),
    "stages[].normal_stress": ("Pa", "simple_shear: σ22 held"),
    "stages[].target_shear_strain": ("–", "simple_shear: stop at this shear strain γ"),
    "solver": ("", "which engine steps the scene, and how"),
    "solver.engine": ("", "dem: grainlab's soft-contact DEM; box2d: Box2D's rigid-body solver"),
    "solver.timestep": ("s", "fixed timestep; 0: `timestep_safety` × the critical timestep"),
    "solver.timestep_safety": ("–", "fraction of the critical timestep 2√(m*/k) used when `timestep` is 0 (box2d: × 10 × it)"),
    "solver.threads": ("", "force-computation threads (dem); results do not depend on it. On the paper's assemblies (about 1,400 particles) two threads ran 1.2-1.4 times as fast as one, in a periodic cell 1.0 (discs) to 1.4 (hexagons); for many runs, run more runs at once instead (--jobs): a batch lends the cores its finished runs leave idle to the runs still going (docs/benchmarks.md, \"Particles numbered along space\" and \"Periodic-cell specimens numbered along space\")"),
    "solver.velocity_iterations": ("", "box2d: b2World::Step's velocity iterations (an error with dem)"),
    "solver.position_iterations": ("", "box2d: b2World::Step's position iterations (an error with dem)"),
    "output": ("", "what is measured and written"),
    "output.sample_interval": ("s", "simulated time between samples outside the shearing stages; 0: automatic"),
    "output.sample_strain": ("–", "axial (or path) strain between samples in the shearing stages"),
    "output.fabric": ("", "measure the anisotropy parameters and stress directions at each sample"),
    "output.histograms": ("", "measure the polar histograms (roses) at each sample; written to histograms.csv"),
    "output.histogram_bins": ("", "bins over [0°, 180°) for the histograms"),
    "output.vtk": ("", "write ParaView frames to DIR/vtk (docs/paraview.md)"),
    "output.vtk_every": ("", "a frame at every vtk_every-th sample (and at the end)"),
    "output.checkpoint_every_s": ("s", "wall time between checkpoints of runs that keep them"),
    "output.stage_checkpoints": ("", "keep the state at each stage's end in DIR/stages/, to start other runs from (default: on with dem, off with box2d; docs/prepared-specimens.md)"),
    "start_from": ("", "start from a prepared specimen instead of preparing one: give `run` with `stage`, or `checkpoint`, or for `grainlab serve` `run_id` with `stage` (docs/prepared-specimens.md)"),
    "start_from.run": ("", "the directory of a run that kept its stages' ends"),
    "start_from.stage": ("", "the stage whose end to start from; the scene's stages up to it are skipped"),
    "start_from.checkpoint": ("", "a stage checkpoint file itself (instead of `run` and `stage`)"),
    "start_from.run_id": ("", "a run stored by `grainlab serve` (its id), whose end of `stage` the server starts from; only the server resolves it (docs/http-api.md)"),
}


def cell(text):
    return str(text).replace("|", "\\|")


def number(x):
    if float(x).is_integer() and abs(x) < 1e15:
        return str(int(x))
    return f"{x:g}"


def value_range(k):
    """As `grainlab scene-keys` prints it: "(0, ∞)", "[1, 100]", "any"."""
    if k["kind"] not in ("number", "integer"):
        return ""
    low, high = k.get("min"), k.get("max")
    if low is None and high is None:
        return "any"
    return (("[" if low is not None and not k["min_open"] else "(") + (number(low) if low is not None else "−∞")
            + ", " + (number(high) if high is not None else "∞")
            + ("]" if high is not None and not k["max_open"] else ")"))


def main():
    catalogue = json.load(sys.stdin)
    keys = catalogue["keys"]
    missing = sorted({k["path"] for k in keys} - set(MEANINGS))
    if missing:
        sys.exit("docs/scene-reference/generate.py: no unit and meaning for " + ", ".join(missing))
    stale = sorted(set(MEANINGS) - {k["path"] for k in keys})
    if stale:
        sys.exit("docs/scene-reference/generate.py: the parser no longer reads " + ", ".join(stale))
    print("# Scene reference\n")
    print("Every key a scene file may hold. Generated from the scene parser's own catalogue of the")
    print("keys it reads (`build/grainlab scene-keys --json`) by")
    print("`build/grainlab scene-keys --json | python3 docs/scene-reference/generate.py > docs/scene-reference.md`;")
    print("the kinds, defaults, ranges, choices and stage types are the parser's, the units and")
    print("meanings are written in generate.py. Do not edit this file by hand: the test")
    print("`docs_scene_reference` fails when it differs from what the parser accepts.\n")
    print("SI units, 2D: forces and stiffnesses per metre of thickness. Ranges are inclusive at `[` `]`,")
    print("exclusive at `(` `)`. A default is the value used when the key is omitted; \"derived\"")
    print("follows from other keys; none: the key is required where it is read, or its absence")
    print("means the feature is unused. Unknown keys are errors. `stages[].x` is a key of each")
    print("stage object; a key read by several stage types with different defaults has a row per")
    print("default. The README's \"Scene JSON\" shows a whole scene.\n")
    print("| key | unit | kind | default | range | choices | stage types | meaning |")
    print("|---|---|---|---|---|---|---|---|")
    for k in keys:
        unit, meaning = MEANINGS[k["path"]]
        default = json.dumps(k["default"], ensure_ascii=False) if k.get("default") is not None else ""
        if default.startswith('"') and default.endswith('"'):
            default = default[1:-1]
        print(f"| `{k['path']}` | {unit} | {k['kind']} | {cell(default)} | {cell(value_range(k))} | "
              f"{cell(', '.join(k.get('choices', [])))} | {cell(', '.join(k.get('stage_types', [])))} | {cell(meaning)} |")


if __name__ == "__main__":
    main()
