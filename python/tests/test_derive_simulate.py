"""kinetics.derive and kinetics.simulate."""

import numpy as np
import pytest
import sympy

import kinetics
from conftest import scene


def test_euler_equations_in_principal_axes():
    euler = kinetics.derive(["euler"], principal=True)["euler"]
    assert euler.text[0] == "SumM_x = I_x*wdot_x - (I_y - I_z)*w_y*w_z"
    x = euler.to_sympy()[0]
    s = {v.name: v for v in x.free_symbols}
    by_hand = s["I_x"] * s["wdot_x"] - (s["I_y"] - s["I_z"]) * s["w_y"] * s["w_z"]
    assert sympy.expand(x.rhs - by_hand) == 0


def test_one_derivation_by_its_name():
    assert kinetics.derive("euler", principal=True)["euler"].text == kinetics.derive(
        ["euler"], principal=True)["euler"].text


def test_an_unknown_derivation_names_the_choices():
    with pytest.raises(ValueError, match="choose from H_G"):
        kinetics.derive(["H_Q"])


def test_sphere_under_an_oscillating_couple_by_hand():
    # I = 2/5 m r² about every axis, so I ω̇_x = M_0 sin(p t): ω_x = w_0 + M_0 (1 - cos p t)/(p I),
    # and ω_y, ω_z keep their values (the scene's comment derives it).
    run = kinetics.simulate(scene("spun_up_sphere.scene"), until=2.0, every=0.5)
    assert isinstance(run.t, np.ndarray)
    assert run.t.tolist() == [0.0, 0.5, 1.0, 1.5, 2.0]
    assert run.omega.shape == (5, 3) and run.orientation.shape == (5, 4)
    inertia = 2 / 5 * 5 * 0.1**2
    by_hand = 1 + 0.02 * (1 - np.cos(2 * run.t)) / (2 * inertia)
    assert np.allclose(run.omega[:, 0], by_hand, rtol=1e-9)
    assert np.allclose(run.omega[:, 1], 0.5) and np.allclose(run.omega[:, 2], 0.0)
    assert np.allclose(np.linalg.norm(run.orientation, axis=1), 1.0)
    assert np.allclose(run.T, 0.5 * inertia * (run.omega**2).sum(axis=1), rtol=1e-12)
    assert np.allclose(run.H, inertia * np.linalg.norm(run.omega, axis=1), rtol=1e-12)
    assert run.method == "integrated"


BOX = """given m = 2 kg
given a = 0.3 m
given b = 0.2 m
given c = 0.1 m
given w_1 = 1 rad/s
given w_2 = 5 rad/s
given w_3 = 0.2 rad/s
body prism(a, b, c) mass m
vbar = 0
omega = w_1*i + w_2*j + w_3*k
find H_G
"""


def test_integrators_agree_with_the_closed_form():
    # A box under no load turning near its middle axis: the closed form (Jacobi's elliptic
    # functions) against DOP853 at a tight tolerance, and T and |H| conserved.
    times = [0.5, 1.0, 2.0]
    exact = kinetics.simulate(BOX, at=times, method="exact")
    dop = kinetics.simulate(BOX, at=times, method="dop853", rtol=1e-12)
    assert exact.method == "exact"
    assert np.allclose(exact.omega, dop.omega, rtol=1e-8, atol=1e-9)
    assert np.ptp(dop.T) <= 1e-9 * dop.T[0] and np.ptp(dop.H) <= 1e-9 * dop.H[0]


def test_settings_a_method_does_not_use_are_refused():
    with pytest.raises(ValueError, match="step does not apply"):
        kinetics.simulate(scene("spun_up_sphere.scene"), until=1.0, method="dop853", step=0.1)
    with pytest.raises(ValueError, match="until"):
        kinetics.simulate(scene("spun_up_sphere.scene"), until=-1.0)
    with pytest.raises(ValueError, match="longer than until"):
        kinetics.simulate(scene("spun_up_sphere.scene"), until=1.0, every=5.0)
    with pytest.raises(ValueError, match="strictly increasing"):
        kinetics.simulate(scene("spun_up_sphere.scene"), at=[1.0, 0.5])


def test_exact_under_a_couple_is_refused_at_the_couple():
    with pytest.raises(kinetics.SceneError) as caught:
        kinetics.simulate(scene("spun_up_sphere.scene"), until=1.0, method="exact")
    assert "couple" in caught.value.source_line and "torque-free" in caught.value.hint
