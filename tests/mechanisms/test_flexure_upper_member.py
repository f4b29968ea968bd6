"""A restrainer on the upper block of a vertical flexure acts on the chain by virtual work.

Issue 34 F14: `rock compare`, `rock assess` and `rock report` refused a wall whose flexure has a
restrainer between its intermediate hinge and its held top ("rock kinematic checks it as
given"). The member's point does not turn about the pivot: its elongation u(θ) (the point's
displacement away from the wall) and u′(θ) = δx, the arm of its force F in the chain's
equation of motion (F·du/dθ), come from the configuration function, tabulated on the chain's
grid (rockcli.mechanisms.table.member_path), and its law is the one every restrainer has.
Checked here: the path against the configuration function; the uplift with a pretension
against the code check's α0 with the same member; the energy of free rocking with an elastic
member; a stiff member that never lets the chain open beyond its static rotation; the two
engines on a yielding tie-rod; and the three commands on the wall that was refused
(tests/data/flexure-upper-tie.toml).
"""

from __future__ import annotations

import json
import math
import random
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

from rockcli.analyses.rocked import mechanism_block, named_spec
from rockcli.cli.main import cli
from rockcli.codecheck.kinematic import Mechanism, alpha0
from rockcli.dynamics.settings import Engine, SolverSettings
from rockcli.dynamics.simulate import simulate
from rockcli.mechanics import Chain, chain_terms, path_terms
from rockcli.mechanisms import motion
from rockcli.mechanisms.catalogue import build
from rockcli.model.derive_wall import to_wall
from rockcli.model.load import load_model

ROOT = Path(__file__).resolve().parents[2]
#: The wall `rock compare` refused: its one mechanism a flexure, a tie-rod on its upper block.
UPPER_TIE = ROOT / "tests" / "data" / "flexure-upper-tie.toml"
#: The casebook's flexure wall: 4 m × 0.25 m, hinges at the edges, nothing on it.
FLEXURE = ROOT / "examples" / "validation" / "models" / "mech-flexure.toml"
MID = "vertical flexure at mid-height"
RICKER = ROOT / "records" / "ricker_Tp0.5s_0.5g.txt"


def spring(k: float, extra: str = "") -> str:
    """A spring 1 m above the mid-height hinge, 0.1 m in from the outer face."""
    return (f'[[restrainers]]\nname = "upper spring"\nk = {k}\nheight = 3.0\n'
            f"from_pivot = 0.1\n{extra}")  # fmt: skip


def flexure_with(tmp_path: Path, extra: str):
    """(model, wall, spec) of the casebook's mid-height flexure with extra TOML."""
    path = tmp_path / "wall.toml"
    path.write_text(FLEXURE.read_text(encoding="utf-8") + "\n" + extra, encoding="utf-8")
    model = load_model(str(path))
    wall = to_wall(model)
    return model, wall, named_spec(wall, MID)


def run(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(cli, list(args))
    return result.exit_code, result.stdout, result.stderr


def test_the_path_is_the_configuration_function(tmp_path: Path) -> None:
    # Cubic Hermite on the chain's grid, u from (u, u′), u′ from (u′, u″): u and u′ to 1e-10
    # of their size at random rotations, the stored values themselves at rest.
    model, wall, spec = flexure_with(tmp_path, spring(1e6))
    block = mechanism_block(model, wall, spec)
    member = block.restrainers[0]
    assert member.path and isinstance(block, Chain)
    rng = random.Random(34)
    for s in (1, -1):
        point = build(wall, spec, s).placement(0)
        assert path_terms(member.path, 0, s, 0.0) == (0.0, point.moment(1.0, 0.0))
        assert member.arm_at_rest(s) == pytest.approx(1.0, rel=1e-12)  # δx = (4 − 3)/(4 − 2)·2
        for _ in range(40):
            a = rng.uniform(0.0, block.table.end)
            u, du = path_terms(member.path, 0, s, a)
            assert u == pytest.approx(point.elongation(a), rel=1e-10)
            assert du == pytest.approx(point.moment(1.0, a), rel=1e-10)
    # The point's place at rest, for reports: its radius and angle from each pivot.
    assert member.r_pos == pytest.approx(math.hypot(0.1, 3.0))


def test_the_uplift_with_a_pretension_is_the_codes_alpha0(tmp_path: Path) -> None:
    # A pretension P0 on the upper block adds P0·δx to the virtual work at rest in both
    # analyses: the engine leaves rest at (G − T + P0·u′(0))/H, the code check's α0 of that
    # member as a spring (code_action "spring"). A ramp of c g/s crosses it at t = α0/c.
    extra = 'pretension = 3000.0\ncode_action = "spring"\n'
    model, wall, spec = flexure_with(tmp_path, spring(2e6, extra))
    block = mechanism_block(model, wall, spec)
    for s in (1, -1):
        code = alpha0(Mechanism(build(wall, spec, s)))
        bare = alpha0(Mechanism(build(to_wall_without(model), spec, s)))
        assert code > bare * 1.5  # the member does raise it
        slope = 0.05 * s
        run_ = simulate(block, np.array([0.0, 40.0]), np.array([0.0, 40.0 * slope]), 0.01)
        assert run_.t_uplift is not None
        assert run_.t_uplift * abs(slope) == pytest.approx(code, rel=1e-12)
        assert math.copysign(1.0, run_.theta_max + run_.theta_min) == s


def to_wall_without(model):
    """The model's wall with no restrainer."""
    return to_wall(model.model_copy(update={"restrainers": []}))


def energy(wall, spec, k: float, theta: float, omega: float) -> float:
    """½·M(θ)·θ̇² + V(θ) + ½·K·u(θ)² from the configuration function."""
    side = build(wall, spec, 1 if theta >= 0 else -1)
    a = abs(theta)
    u = side.placement(0).elongation(a)
    return (
        0.5 * motion.generalised_mass(side, a) * omega**2
        + motion.potential(side, a)
        + (0.5 * k * u * u)
    )


def test_free_rocking_with_an_elastic_member_conserves_energy(tmp_path: Path) -> None:
    # e = 1, an elastic spring of no strength limit on the upper block: the member's force
    # does the work F·du along the path, so the Lagrangian's energy plus ½·K·u² stays put.
    k = 2e5
    model, wall, spec = flexure_with(tmp_path, spring(k) + "\n[restitution]\ne = 1.0\n")
    block = mechanism_block(model, wall, spec)
    assert block.e == 1.0 and block.restitution(-1) == 1.0
    theta0 = 0.6 * block.alpha
    time = np.arange(0.0, 6.0 + 1e-9, 0.01)
    settings = SolverSettings(rtol=1e-11, atol=1e-12, tail=0.0)
    run_ = simulate(block, time, np.zeros_like(time), 0.01, settings=settings, history=True,
                    theta0=theta0)  # fmt: skip
    assert run_.impacts >= 6
    hist = run_.history
    assert hist is not None and hist.elongations is not None
    e0 = energy(wall, spec, k, theta0, 0.0)
    assert 0.5 * k * build(wall, spec, 1).placement(0).elongation(theta0) ** 2 > 0.05 * e0
    worst = max(abs(energy(wall, spec, k, th, om) - e0)
                for th, om in zip(hist.theta, hist.omega, strict=True))  # fmt: skip
    assert worst <= 1e-8 * e0
    # The history's elongations are the member's path (for the force–elongation loops).
    on = hist.theta > 0
    want = [build(wall, spec, 1).placement(0).elongation(a) for a in hist.theta[on][:50]]
    assert np.allclose(hist.elongations[0][on][:50], want, rtol=1e-9, atol=1e-15)


def test_a_stiff_member_holds_the_chain_at_its_static_rotation(tmp_path: Path) -> None:
    # K = 1e10 N/m on the upper block, a slow pulse of twice the uplift acceleration: the
    # chain opens only as far as the member's static balance K·u′(0)²·θ = üg·H − G (the
    # restrained chain's own period is milliseconds), never past twice it; without the member
    # it rocks four orders of magnitude more.
    k = 1e10
    model, wall, spec = flexure_with(tmp_path, spring(k))
    block = mechanism_block(model, wall, spec)
    assert isinstance(block, Chain)
    peak = 2.0 * block.uplift_acceleration
    time = np.arange(0.0, 3.0, 0.002)
    accel = peak * np.sin(2 * np.pi * time / 0.5) * (time < 1.0)
    held = simulate(block, time, accel, 0.002)
    for s, extreme in ((1, held.theta_max), (-1, -held.theta_min)):
        g, h, _, _, _ = chain_terms(block.table.table, s, 0.0)
        static = (peak * h - g) / (k * block.restrainers[0].arm_at_rest(s) ** 2)
        assert static <= extreme <= 2.0 * static
    bare = simulate(mechanism_block(*flexure_with(tmp_path, "")), time, accel, 0.002)
    assert bare.theta_max > 1e4 * held.theta_max


def test_the_engines_agree_on_a_yielding_tie_rod() -> None:
    # The fast engine reads the path's table, the reference the chain's configuration function
    # and the same path: the peak and the tie-rod's demand to 1e-6, its yield at the same time.
    model = load_model(str(UPPER_TIE))
    wall = to_wall(model)
    block = mechanism_block(model, wall, named_spec(wall, "vertical flexure, storey 1"))
    assert [r.name for r in block.restrainers] == ["tie-rod"] and block.restrainers[0].path
    time = np.arange(0.0, 3.0, 0.005)
    accel = 2.5 * np.sin(2 * np.pi * time / 0.5) * (time < 1.0)
    fast = simulate(block, time, accel, 0.005)
    ref = simulate(block, time, accel, 0.005, engine=Engine.REFERENCE)
    assert fast.impacts == ref.impacts and fast.impacts >= 2
    assert fast.max_ratio == pytest.approx(ref.max_ratio, rel=1e-6)
    tie_fast, tie_ref = fast.restrainers[0], ref.restrainers[0]
    assert tie_fast.t_yield is not None and tie_ref.t_yield is not None
    assert tie_fast.t_yield == pytest.approx(tie_ref.t_yield, abs=1e-6)
    assert tie_fast.max_force == pytest.approx(tie_ref.max_force, rel=1e-6)
    assert tie_fast.max_displacement == pytest.approx(tie_ref.max_displacement, rel=1e-6)


def test_compare_assess_and_report_rock_the_wall_they_refused(tmp_path: Path) -> None:
    code, out, err = run("compare", str(UPPER_TIE), "--record", str(RICKER), "--format", "json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["rocking"]["mechanism"] == {"name": "vertical flexure, storey 1",
                                           "type": "vertical-flexure"}  # fmt: skip
    runs = doc["rocking"]["runs"]
    assert all(r["restrainers"][0]["max_force"] > 0.0 for r in runs)  # the tie-rod worked
    code, out, err = run("assess", str(UPPER_TIE), "--record", str(RICKER), "--format", "json")
    assert code == 0, err
    assert [r["name"] for r in json.loads(out)["model"]["restrainers"]] == ["tie-rod"]
    report = tmp_path / "report.html"
    code, out, err = run("report", str(UPPER_TIE), "--record", str(RICKER), "--output",
                         str(report))  # fmt: skip
    assert code == 0, err
    assert report.stat().st_size > 0
