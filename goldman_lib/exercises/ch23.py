"""Exercise checkers for chapter 23, radiosity (Goldman §23.2-23.5).

Every numeric exercise deals new instances (issue 17 §3, :mod:`goldman_lib.exercises.deal`): instance 0
is the module constants below, which the stored notebook shows; ``deal("check_...")`` (or the button
beside the exercise) deals another, and the checker, ``PROBLEMS`` and ``steps("check_...")`` follow the
current instance.  ``SLIPS`` holds the wrong answers each checker recognises, for the stored instance.
``None`` or ``...`` means "not answered yet".  The data differ from the chapter's worked examples.
The chapter's "show that" exercises (in :mod:`goldman_lib.exercises.proofs`) ask for an identity and
the programming project, :func:`check_progressive_refinement_project` (the learner's shooting solver
on generated scenes with reciprocal form factors, against the exact solution of B = E + rho F B),
already runs on generated cases: neither deals.

>>> print(check_reciprocity(0.12).message)
that is F_ij itself: form factors are not symmetric; A_i F_ij = A_j F_ji, so F_ji = A_i F_ij / A_j.
"""

from __future__ import annotations

import numpy as np

from goldman_lib import radiosity as rd
from goldman_lib.exercises import far_off, guard_checkers
from goldman_lib.exercises import Result, correct, fmt, off_by, read_number, wrong
from goldman_lib.exercises import read_vector as _pair  # the shared reader
from goldman_lib.exercises.deal import Deck, steps_number as _f, within
from goldman_lib.exercises.projects import Case, check_project

__all__ = ["PROBLEMS", "SLIPS", "JACOBI_F", "JACOBI_RHO", "JACOBI_E", "GS_F", "GS_RHO", "GS_E", "RECIPROCITY",
           "SQUARE_SIDE", "SQUARE_DISTANCE", "SHOT_AREA", "SHOT_F", "SHOT_RHO", "SHOT_DB",
           "check_jacobi_step", "check_gauss_seidel_step", "check_reciprocity", "check_parallel_form_factor",
           "DECK", "deal", "steps", "current", "deal_button",
           "check_shot", "check_progressive_refinement_project", "project_cases"]

#: Exercise 1 (§23.5): a 2-patch system (A_1 = 1, A_2 = 2, so A_1 F_12 = A_2 F_21).
JACOBI_F = ((0.0, 0.4), (0.2, 0.0))
JACOBI_RHO = (0.5, 0.8)
JACOBI_E = (2.0, 1.0)
#: Exercise 2 (§23.5): the same form factors, other reflectances and emissions.
GS_F = JACOBI_F
GS_RHO = (0.6, 0.5)
GS_E = (1.0, 3.0)
#: Exercise 3 (§23.3): areas A_i, A_j and the form factor F_ij.
RECIPROCITY = (2.5, 0.8, 0.12)
#: Exercise 4 (§23.3): two directly opposed squares.
SQUARE_SIDE = 2.0
SQUARE_DISTANCE = 1.0
#: Exercise 5 (§23.5): three patches, the shooter's row of F, reflectances and unshot radiosities.
SHOT_AREA = (2.0, 1.0, 0.5)
SHOT_F = (0.0, 0.3, 0.1)           # F_1j: what patch 1 sees
SHOT_RHO = (0.5, 0.5, 0.8)
SHOT_DB = (1.5, 1.0, 2.0)

DECK = Deck("ch23")


def _m(rows) -> str:
    return "[" + ", ".join("[" + ", ".join(fmt(v) for v in r) + "]" for r in rows) + "]"


def _tenths(rng, lo, hi) -> float:
    """A multiple of 0.1 in [lo, hi] (hand-friendly reflectances and form factors)."""
    return round(int(rng.integers(round(lo * 10), round(hi * 10) + 1)) / 10, 1)


def _close(a, b, tol=1e-4) -> bool:
    return bool(np.all(np.abs(np.asarray(a, float) - np.asarray(b, float)) <= tol * np.maximum(1, np.abs(b))))


def _dist(a, b) -> str:
    return far_off(a, b)


def _jacobi(F, rho, E):
    F, rho, E = np.array(F), np.array(rho), np.array(E)
    return E + rho * (F @ E)


def _gs(F, rho, E, order=(0, 1)):
    F, rho, E = np.array(F), np.array(rho), np.array(E, dtype=float)
    B = E.copy()
    for i in order:
        B[i] = E[i] + rho[i] * (F[i] @ B)
    return B


def _system(p):
    return np.array(p["F"], float), np.array(p["rho"], float), np.array(p["E"], float)


def _first_sweep(solver, p):
    """The first iterate of the library's ``solver`` (:func:`radiosity.jacobi` or
    :func:`radiosity.gauss_seidel`) from B^(0) = E."""
    F, rho, E = _system(p)
    return solver(F, rho, E, tol=1e-300, max_iter=1, full_output=True)[1].history[1]


def _two_patch_generate(rng) -> dict:
    F12, F21 = _tenths(rng, 0.1, 0.6), _tenths(rng, 0.1, 0.6)
    return {"F": ((0.0, F12), (F21, 0.0)), "rho": (_tenths(rng, 0.2, 0.9), _tenths(rng, 0.2, 0.9)),
            "E": (float(rng.integers(1, 5)), float(rng.integers(1, 5)))}


def _two_patch_ok(p):
    F = p["F"]
    if F[0][1] == F[1][0]:
        return "F_12 = F_21 (equal areas): the transposed form factors would be right too"
    return None


#: the checkers' tolerance is relative 1e-4; instances keep their answers 1e-3 apart
_SAME = within(1e-3, relative=True)

# -- §23.5: Jacobi ----------------------------------------------------------------------------------------

_STORED_JACOBI = {"F": JACOBI_F, "rho": JACOBI_RHO, "E": JACOBI_E}


def _jacobi_answer(p):
    return _first_sweep(rd.jacobi, p)


def _jacobi_slips(p):
    F, rho, E = _system(p)
    return {"Gauss-Seidel": _gs(F, rho, E), "F transposed": _jacobi(F.T, rho, E), "no reflectance": E + F @ E,
            "no emission": rho * (F @ E)}


def _jacobi_statement(p) -> str:
    F = p["F"]
    return (f"Two patches have form factors F = {_m(F)} (F_12 = {fmt(F[0][1])}: patch 1 sends that "
            f"fraction of its light to patch 2), reflectances rho = {fmt(p['rho'])} and emissions E = {fmt(p['E'])}. "
            f"Start from B^(0) = E and make one Jacobi step B_i^(1) = E_i + rho_i sum_j F_ij B_j^(0). Give "
            f"[B_1, B_2] (Goldman §23.5).")


def _jacobi_steps(p) -> str:
    F, rho, E = _system(p)
    B = _jacobi_answer(p)
    return (f"1. Jacobi gathers from B^(0) = E = {fmt(E)} only.\n"
            f"2. B_1 = E_1 + rho_1 F_12 B_2^(0) = {fmt(E[0])} + {fmt(rho[0])}·{fmt(F[0, 1])}·{fmt(E[1])} = {_f(B[0])}.\n"
            f"3. B_2 = E_2 + rho_2 F_21 B_1^(0) = {fmt(E[1])} + {fmt(rho[1])}·{fmt(F[1, 0])}·{fmt(E[0])} = {_f(B[1])} "
            f"(B_1^(0) = E_1, not the new B_1).")


@DECK.exercise(stored=_STORED_JACOBI, generate=_two_patch_generate, answer=_jacobi_answer, slips=_jacobi_slips,
               statement=_jacobi_statement, steps=_jacobi_steps, same=_SAME, well_posed=_two_patch_ok)
def check_jacobi_step(answer, p) -> Result:
    """Check one Jacobi step ``B^(1) = E + rho F E`` of the statement's two patches (Goldman §23.5).
    Recognises a Gauss-Seidel sweep, the transposed form factors, a missing reflectance and a missing emission.
    """
    got, err = _pair(answer, "your [B_1, B_2]", 2, "[B_1, B_2]")
    if err is not None:
        return err
    F, rho, E = _system(p)
    right = _jacobi_answer(p)
    if _close(got, right):
        return correct("one bounce of light: each patch keeps its emission and gathers rho_i F_ij B_j from the other.")
    if _close(got, _gs(F, rho, E)):
        return wrong("that is a Gauss-Seidel sweep: you used patch 1's new radiosity for patch 2. Jacobi gathers "
                     "from B^(0) only.")
    if _close(got, _jacobi(F.T, rho, E)):
        return wrong("you used F_ji where F_ij belongs: patch i gathers sum_j F_ij B_j, row i of F.")
    if _close(got, E + F @ E):
        return wrong("the reflectance is missing: a patch reflects only rho_i of the light it gathers.")
    if _close(got, rho * (F @ E)):
        return wrong("that is only the gathered light; add the patch's own emission E_i.")
    return wrong(f"your [B_1, B_2] is {_dist(got, right)}; compute E_i + rho_i (F_i1 B_1 + F_i2 B_2) with B = E.")


# -- §23.5: Gauss-Seidel ------------------------------------------------------------------------------------

_STORED_GS = {"F": GS_F, "rho": GS_RHO, "E": GS_E}


def _gs_answer(p):
    return _first_sweep(rd.gauss_seidel, p)


def _gs_slips(p):
    F, rho, E = _system(p)
    return {"Jacobi": _jacobi(F, rho, E), "patch 2 first": _gs(F, rho, E, order=(1, 0)),
            "no emission": _gs_answer(p) - E}


def _gs_statement(p) -> str:
    head = ("Same form factors F = " if p["F"] == JACOBI_F else "Two patches have form factors F = ")
    return (f"{head}{_m(p['F'])}, now rho = {fmt(p['rho'])} and E = {fmt(p['E'])}. Start from B^(0) = E and "
            f"make one Gauss-Seidel sweep, patch 1 first, each patch gathering from the newest radiosities. Give "
            f"[B_1, B_2] after the sweep (Goldman §23.5).")


def _gs_steps(p) -> str:
    F, rho, E = _system(p)
    B = _gs_answer(p)
    return (f"1. Start from B = E = {fmt(E)}.\n"
            f"2. Patch 1: B_1 = E_1 + rho_1 F_12 B_2 = {fmt(E[0])} + {fmt(rho[0])}·{fmt(F[0, 1])}·{fmt(E[1])} = {_f(B[0])}.\n"
            f"3. Patch 2 gathers from the new B_1: B_2 = E_2 + rho_2 F_21 B_1 = {fmt(E[1])} + "
            f"{fmt(rho[1])}·{fmt(F[1, 0])}·{_f(B[0])} = {_f(B[1])}.")


@DECK.exercise(stored=_STORED_GS, generate=_two_patch_generate, answer=_gs_answer, slips=_gs_slips,
               statement=_gs_statement, steps=_gs_steps, same=_SAME, well_posed=_two_patch_ok)
def check_gauss_seidel_step(answer, p) -> Result:
    """Check one Gauss-Seidel sweep, patch 1 first, of the statement's two patches (Goldman §23.5).
    Recognises the Jacobi step, the sweep in the other order and a missing emission.
    """
    got, err = _pair(answer, "your [B_1, B_2]", 2, "[B_1, B_2]")
    if err is not None:
        return err
    F, rho, E = _system(p)
    right = _gs_answer(p)
    if _close(got, right):
        return correct("patch 2 already saw patch 1's updated radiosity: that is why Gauss-Seidel needs fewer sweeps.")
    if _close(got, _jacobi(F, rho, E)):
        return wrong("that is the Jacobi step: patch 2 should gather from patch 1's radiosity as updated in this sweep.")
    if _close(got, _gs(F, rho, E, order=(1, 0))):
        return wrong("you swept patch 2 first; the sweep goes in patch order, patch 1 first.")
    if _close(got, _gs(F, rho, np.zeros(2)) + 0) or _close(got, right - E):
        return wrong("the emission is missing: B_i = E_i + rho_i sum_j F_ij B_j.")
    return wrong(f"your [B_1, B_2] is {_dist(got, right)}; update B_1 first, then use it for B_2.")


# -- §23.3: reciprocity -------------------------------------------------------------------------------------

_STORED_RECIPROCITY = {"Ai": RECIPROCITY[0], "Aj": RECIPROCITY[1], "Fij": RECIPROCITY[2]}
_AREAS = (0.5, 0.8, 1.0, 1.2, 1.5, 2.0, 2.5, 3.0, 4.0)
_FIJ = (0.05, 0.1, 0.12, 0.15, 0.2, 0.24, 0.25, 0.3, 0.4)


def _reciprocity_answer(p) -> float:
    return p["Ai"] * p["Fij"] / p["Aj"]


def _reciprocity_slips(p):
    return {"upside down": p["Aj"] * p["Fij"] / p["Ai"], "F_ij itself": p["Fij"], "1 - F_ij": 1 - p["Fij"]}


def _reciprocity_generate(rng) -> dict:
    Ai, Aj = rng.choice(_AREAS, size=2, replace=False)
    return {"Ai": float(Ai), "Aj": float(Aj), "Fij": float(rng.choice(_FIJ))}


def _reciprocity_ok(p):
    if _reciprocity_answer(p) > 1:
        return "F_ji would exceed 1: patch i cannot send that much to a smaller patch j"
    return None


def _reciprocity_statement(p) -> str:
    return (f"Patch i has area {fmt(p['Ai'])}, patch j area {fmt(p['Aj'])}, and F_ij = "
            f"{fmt(p['Fij'])}. What is F_ji (Goldman §23.3)?")


def _reciprocity_steps(p) -> str:
    return (f"1. Reciprocity: A_i F_ij = A_j F_ji (both are the power exchanged between the patches, per unit radiosity).\n"
            f"2. F_ji = A_i F_ij / A_j = {fmt(p['Ai'])}·{fmt(p['Fij'])}/{fmt(p['Aj'])} = {_f(_reciprocity_answer(p))}.")


@DECK.exercise(stored=_STORED_RECIPROCITY, generate=_reciprocity_generate, answer=_reciprocity_answer,
               slips=_reciprocity_slips, statement=_reciprocity_statement, steps=_reciprocity_steps,
               same=within(1e-3), well_posed=_reciprocity_ok)
def check_reciprocity(answer, p) -> Result:
    """Check ``F_ji = A_i F_ij / A_j`` for the statement's areas (Goldman §23.3).  Recognises the ratio
    upside down, F_ij itself and the complement ``1 - F_ij``.

    >>> print(check_reciprocity(0.0384).message)
    you divided the wrong way: A_i F_ij = A_j F_ji, so F_ji = A_i F_ij / A_j (the smaller patch sees more of the bigger one).
    """
    value, err = read_number(answer, "your F_ji")
    if err is not None:
        return err
    Ai, Aj, Fij = p["Ai"], p["Aj"], p["Fij"]
    right = Ai * Fij / Aj
    if abs(value - right) <= 1e-4:
        return correct("A_i F_ij = A_j F_ji: the smaller patch sees a larger share of the bigger one.")
    if abs(value - Aj * Fij / Ai) <= 1e-4:
        return wrong("you divided the wrong way: A_i F_ij = A_j F_ji, so F_ji = A_i F_ij / A_j (the smaller patch "
                     "sees more of the bigger one).")
    if abs(value - Fij) <= 1e-4:
        return wrong("that is F_ij itself: form factors are not symmetric; A_i F_ij = A_j F_ji, so F_ji = A_i F_ij / A_j.")
    if abs(value - (1 - Fij)) <= 1e-4:
        return wrong("1 - F_ij is what patch i sends elsewhere, not what j sends to i; use reciprocity.")
    return wrong(f"your F_ji is {off_by(value, right)}; use A_i F_ij = A_j F_ji.")


# -- §23.3: the closed form for opposed squares ---------------------------------------------------------

_STORED_SQUARES = {"side": SQUARE_SIDE, "d": SQUARE_DISTANCE}


def _squares_answer(p) -> float:
    return rd.form_factor_parallel_rectangles(p["side"], p["side"], p["d"])


def _squares_slips(p):
    s, d = p["side"], p["d"]
    return {"X = distance / side": rd.form_factor_parallel_rectangles(d, d, s),
            "A / (pi d^2)": s ** 2 / (np.pi * d ** 2), "unit squares": rd.form_factor_parallel_rectangles(1, 1, 1)}


def _squares_generate(rng) -> dict:
    return {"side": float(rng.choice([0.5, 1.0, 1.5, 2.0, 3.0, 4.0])), "d": float(rng.choice([0.5, 1.0, 2.0, 3.0]))}


def _squares_ok(p):
    if p["side"] == p["d"]:
        return "side = distance: X = Y = 1, the unit squares' value would be right"
    return None


def _squares_statement(p) -> str:
    return (f"Two {fmt(p['side'])} x {fmt(p['side'])} squares face each other, directly opposed, "
            f"{fmt(p['d'])} apart. Use the closed form for directly opposed rectangles to give their form "
            f"factor F to 3 decimals (Goldman §23.3).")


def _squares_steps(p) -> str:
    X = p["side"] / p["d"]
    return (f"1. X = Y = side / distance = {fmt(p['side'])}/{fmt(p['d'])} = {_f(X)}.\n"
            f"2. The closed form for directly opposed rectangles (Goldman §23.3) with these X and Y "
            f"(radiosity.form_factor_parallel_rectangles({fmt(p['side'])}, {fmt(p['side'])}, {fmt(p['d'])})) "
            f"gives F = {_f(_squares_answer(p))}.")


@DECK.exercise(stored=_STORED_SQUARES, generate=_squares_generate, answer=_squares_answer, slips=_squares_slips,
               statement=_squares_statement, steps=_squares_steps, same=within(2e-3), well_posed=_squares_ok)
def check_parallel_form_factor(answer, p) -> Result:
    """Check the closed form for the statement's two directly opposed squares (Goldman §23.3).  Recognises
    the ratio X = distance / side, the small-patch estimate A / (pi d^2) and the unit-square value.

    >>> print(check_parallel_form_factor(1.2732).message)
    that is A / (pi d^2), the estimate for small, distant patches: it even exceeds 1 here. Use the closed form.
    """
    value, err = read_number(answer, "your F")
    if err is not None:
        return err
    side, d = p["side"], p["d"]
    right = _squares_answer(p)
    if abs(value - right) <= 6e-4:
        if side > d:
            return correct("bigger squares at the same distance catch much more of each other's light than unit squares.")
        return correct("squares small against their distance catch little of each other's light.")
    if abs(value - rd.form_factor_parallel_rectangles(d, d, side)) <= 6e-4:
        return wrong("you used X = distance / side; the closed form takes X = width / distance and Y = height / distance.")
    small = side ** 2 / (np.pi * d ** 2)
    if abs(value - small) <= 6e-4:
        return wrong("that is A / (pi d^2), the estimate for small, distant patches"
                     + (": it even exceeds 1 here. Use the closed form." if small > 1 else
                        ", which ignores the angles across the squares. Use the closed form."))
    if abs(value - rd.form_factor_parallel_rectangles(1, 1, 1)) <= 6e-4:
        return wrong("that is the value for unit squares at unit distance; here X = Y = side / distance is not 1.")
    return wrong(f"your F is {off_by(value, right)}; evaluate the closed form with X = Y = side / distance.")


# -- §23.5: one shot of progressive refinement -------------------------------------------------------------

_STORED_SHOT = {"area": SHOT_AREA, "F": SHOT_F, "rho": SHOT_RHO, "dB": SHOT_DB}


def _shot(F_row, area, rho, dB, reciprocal=True, zero=True, reflect=True):
    F_row, area, rho, dB = (np.array(a, float) for a in (F_row, area, rho, dB))
    F_back = F_row * area[0] / area if reciprocal else F_row
    out = dB + (rho if reflect else 1.0) * F_back * dB[0]
    out[0] = 0.0 if zero else dB[0]
    return out


def _shot_args(p):
    return p["F"], p["area"], p["rho"], p["dB"]


def _shot_answer(p):
    """The unshot radiosities after one shot of :func:`radiosity.progressive_refinement` from the unshot
    radiosities dB (only row 1 of F is known, and only row 1 is read: patch 1 shoots)."""
    F = np.zeros((3, 3))
    F[0] = p["F"]
    dB = np.array(p["dB"], float)
    _, h = rd.progressive_refinement(F, p["rho"], dB, p["area"], tol=1e-300, max_iter=1, full_output=True)
    out = h.history[1].copy()          # B after the shot = dB + what arrived; the shooter's dB is cleared
    out[h.shooters[0]] = 0.0
    return out


def _shot_slips(p):
    args = _shot_args(p)
    return {"no reciprocity": _shot(*args, reciprocal=False), "dB_1 kept": _shot(*args, zero=False),
            "no reflectance": _shot(*args, reflect=False)}


def _shot_generate(rng) -> dict:
    return {"area": tuple(float(a) for a in rng.choice([0.5, 1.0, 2.0, 3.0], size=3)),
            "F": (0.0, _tenths(rng, 0.1, 0.5), _tenths(rng, 0.1, 0.4)),
            "rho": tuple(_tenths(rng, 0.2, 0.9) for _ in range(3)),
            "dB": tuple(float(v) / 2 for v in rng.integers(1, 7, size=3))}


def _shot_ok(p):
    A, dB, F = np.array(p["area"]), np.array(p["dB"]), np.array(p["F"])
    power = A * dB
    if not power[0] > max(power[1], power[2]):
        return "patch 1 does not have the most unshot power A dB: it would not shoot"
    if np.any(F * A[0] / A > 1):
        return "a form factor F_j1 = A_1 F_1j / A_j would exceed 1"
    return None


def _shot_statement(p) -> str:
    F = p["F"]
    return (f"Progressive refinement: three patches with areas {fmt(p['area'])}, reflectances {fmt(p['rho'])} and "
            f"unshot radiosities dB = {fmt(p['dB'])}. Patch 1 has the most unshot power A dB, so it shoots; its form "
            f"factors are F_12 = {fmt(F[1])}, F_13 = {fmt(F[2])}. Give the unshot radiosities [dB_1, dB_2, dB_3] after "
            f"the shot (Goldman §23.5).")


def _shot_steps(p) -> str:
    A, F, rho, dB = (np.array(p[k], float) for k in ("area", "F", "rho", "dB"))
    out = _shot_answer(p)
    back = F * A[0] / A
    return (f"1. The unshot powers A dB = {fmt(A * dB)}: patch 1 shoots.\n"
            f"2. Reciprocity: F_21 = A_1 F_12 / A_2 = {_f(back[1])}, F_31 = A_1 F_13 / A_3 = {_f(back[2])}.\n"
            f"3. Patch j receives rho_j F_j1 dB_1: dB_2 = {fmt(dB[1])} + {fmt(rho[1])}·{_f(back[1])}·{fmt(dB[0])} = "
            f"{_f(out[1])}, dB_3 = {fmt(dB[2])} + {fmt(rho[2])}·{_f(back[2])}·{fmt(dB[0])} = {_f(out[2])}.\n"
            f"4. Patch 1 has shot all it had: dB_1 = 0.")


@DECK.exercise(stored=_STORED_SHOT, generate=_shot_generate, answer=_shot_answer, slips=_shot_slips,
               statement=_shot_statement, steps=_shot_steps, same=_SAME, well_posed=_shot_ok)
def check_shot(answer, p) -> Result:
    """Check one shot of progressive refinement from the statement's patch 1 (Goldman §23.5).  Recognises
    F_1j used without reciprocity, the shooter's unshot radiosity not cleared, and a missing reflectance.

    >>> print(check_shot([0, 1.225, 2.12]).message)
    you used F_1j where patch j receives through F_j1 = A_1 F_1j / A_j (reciprocity).
    """
    got, err = _pair(answer, "your [dB_1, dB_2, dB_3]", 3, "[dB_1, dB_2, dB_3]")
    if err is not None:
        return err
    args = _shot_args(p)
    right = _shot_answer(p)
    if _close(got, right):
        return correct("patch 1's unshot light is now spread to the others, each receiving rho_j F_j1 dB_1.")
    if _close(got, _shot(*args, reciprocal=False)):
        return wrong("you used F_1j where patch j receives through F_j1 = A_1 F_1j / A_j (reciprocity).")
    if _close(got, _shot(*args, zero=False)):
        return wrong("after shooting, patch 1 has no unshot radiosity left: clear its dB.")
    if _close(got, _shot(*args, reflect=False)):
        return wrong("the reflectance is missing: patch j keeps rho_j of what arrives.")
    return wrong(f"your [dB_1, dB_2, dB_3] is {_dist(got, right)}; add rho_j F_j1 dB_1 to each dB_j, then clear dB_1.")


#: Deal another instance of an exercise (``deal("check_shot")``, or with ``seed=``; 0 is the stored
#: one), show the worked steps of the current one, read it, or get a button.
deal, steps, current, deal_button = DECK.deal, DECK.steps, DECK.current, DECK.button
PROBLEMS = DECK.problems({})


# -- the programming project --------------------------------------------------------------------------

def _random_scene(rng, n):
    area = rng.uniform(0.3, 3.0, n)
    S = rng.uniform(0.0, 1.0, (n, n))
    S = S + S.T
    np.fill_diagonal(S, 0.0)
    F = S / area[:, None]
    F = F / F.sum(axis=1).max() * rng.uniform(0.6, 0.95)          # rows <= 1; A F symmetric
    rho = rng.uniform(0.1, 0.9, n)
    E = np.zeros(n)
    E[rng.choice(n, size=max(1, n // 4), replace=False)] = rng.uniform(1.0, 5.0, max(1, n // 4))
    return F, rho, E, area


def _closed_reciprocal(F, area, sweeps: int = 200) -> np.ndarray:
    """Form factors with both closure and reciprocity exact: symmetrise A F into S, then scale S
    symmetrically (S -> D S D, Sinkhorn's balancing) until row i of S sums to A_i.  Then F = S / A
    has rows summing to 1 and A F = S symmetric, so shooting (which reads only row i of F and
    F_ji = A_i F_ij / A_j) and gathering (B = E + rho F B) solve one and the same equation."""
    S = area[:, None] * F
    S = (S + S.T) / 2
    x = np.ones(len(area))
    for _ in range(sweeps):
        x = np.sqrt(x * area / (S @ x))
    S = x[:, None] * S * x[None, :]
    S = (S + S.T) / 2
    return S / area[:, None]


def project_cases(seed: int = 23) -> list[Case]:
    """The cases of :func:`check_progressive_refinement_project`, from a fixed seed: random scenes with
    unequal areas (reciprocal form factors), a closed box (rows of F summing to 1, and reciprocal),
    a scene that emits nothing, one with a black patch, and a single patch.  In every case A_i F_ij =
    A_j F_ji holds to rounding, so the radiosities B = E + rho F B are the same whether a shooter
    computes F_ji = A_i F_ij / A_j or reads F[j, i]."""
    rng = np.random.default_rng(seed)
    cases = []
    for n in (4, 9):
        F, rho, E, area = _random_scene(rng, n)
        cases.append(Case(f"a random scene of {n} patches with unequal areas", (F, rho, E, area), kind="random scene"))
    box = rd.cornell_box(2, closed=True, blocks=False)
    F = _closed_reciprocal(rd.hemicube_form_factors(box, 16), box.areas)
    cases.append(Case(f"a closed box of {len(box)} patches (rows of F sum to 1), lit from the ceiling",
                      (F, box.reflectance[:, 0].copy(), box.emission[:, 0].copy(), box.areas), kind="closed box"))
    F, rho, E, area = _random_scene(rng, 5)
    cases.append(Case("a scene of 5 patches that emits nothing", (F, rho, np.zeros(5), area), kind="no emission"))
    F, rho, E, area = _random_scene(rng, 6)
    rho = rho.copy()
    rho[np.argmax(E)] = 0.0
    rho[0] = 0.0
    cases.append(Case("6 patches, two of them black (rho = 0)", (F, rho, E, area), kind="black patch"))
    cases.append(Case("a single patch (F = [[0]]) emitting 2", (np.zeros((1, 1)), np.array([0.5]), np.array([2.0]),
                                                                 np.array([1.5])), kind="one patch"))
    return cases


def _solve(G, rho, E):
    """The B with B = E + rho (G B), by a direct solve."""
    n = len(E)
    return np.linalg.solve(np.eye(n) - np.asarray(rho, float)[:, None] * G, np.asarray(E, float))


def _reference(F, rho, E, area):
    """The radiosities: the exact solution of B = E + rho F B (what the starter cell promises)."""
    return _solve(np.asarray(F, float), rho, E)


#: The project's tolerance: each B_i within PROJECT_TOL * max(1, max |B|) of the solution.
PROJECT_TOL = 1e-6


def _compare(got, expected, case):
    arr = np.asarray(got, dtype=float)
    exp = np.asarray(expected, dtype=float)
    if arr.shape != exp.shape:
        return f"it has shape {arr.shape}; the radiosities have shape {exp.shape} (one per patch)"
    if not np.all(np.isfinite(arr)):
        return "it contains NaN or infinite values"
    scale = PROJECT_TOL * max(1.0, np.abs(exp).max())
    err = np.abs(arr - exp)
    if err.max() <= scale:
        return None
    F, rho, E, area = (np.asarray(a, float) for a in case.args)
    k = int(np.argmax(err))
    head = f"patch {k} has radiosity {fmt(arr[k])}, expected {fmt(exp[k])} ({int((err > scale).sum())} of {len(exp)} patches off)"
    near = lambda B: B is not None and np.all(np.isfinite(B)) and np.abs(arr - B).max() <= scale  # noqa: E731
    ratio = area[:, None] / area[None, :]
    slips = [
        (lambda: E + rho * (F @ E), "that is one gathering step, E + rho F E (light that bounced once): shoot until "
                                    "the unshot radiosity is negligible"),
        (lambda: _solve(F.T, rho, E), "patch j received rho_j F_ij dB_i: the form factor from i to j read as F_ji; "
                                      "by reciprocity F_ji = A_i F_ij / A_j"),
        (lambda: _solve((F * ratio.T).T, rho, E), "patch j received rho_j (A_j F_ij / A_i) dB_i: the area ratio is "
                                                  "upside down; F_ji = A_i F_ij / A_j"),
        (lambda: _solve(F * rho[None, :], np.ones_like(rho), E), "patch j received rho_i F_ji dB_i: the shooter's "
                                                                  "reflectance; it is the receiver's, rho_j"),
        (lambda: _solve(F, np.ones_like(rho), E) if np.all(np.abs(np.linalg.eigvals(F)) < 1 - 1e-9) else None,
         "the reflectance rho_j is missing from what patch j receives"),
    ]
    for make, why in slips:
        try:
            B = make()
        except np.linalg.LinAlgError:
            continue
        if near(B) and not near(exp):
            return head + "; " + why
    if np.all(arr <= exp + scale):
        return head + "; every patch is at or below the solution: did you shoot until the unshot radiosity is negligible?"
    return head


def check_progressive_refinement_project(function) -> Result:
    """Check the learner's ``progressive_refinement(F, rho, E, area)`` (one channel: ``F`` ``(n, n)``,
    ``rho``, ``E``, ``area`` ``(n,)``; returns the radiosities ``(n,)``) on :func:`project_cases`:
    each B_i must be within 1e-6 * max(1, max B) of the exact solution of B = E + rho F B (the form
    factors of every case are reciprocal, so shooting and a direct solve agree) (Goldman §23.5).

    >>> def gather_once(F, rho, E, area):
    ...     return E + rho * (F @ E)
    >>> print(check_progressive_refinement_project(gather_once).message)   # doctest: +ELLIPSIS
    case 1 of 6 (a random scene of 4 patches with unequal areas): ... that is one gathering step, ...
    """
    return check_project(function, project_cases(), reference=_reference, compare=_compare,
                         what="progressive refinement",
                         hint="shoot from the patch with the largest A_i dB_i; patch j receives rho_j F_ji dB_i with "
                              "F_ji = A_i F_ij / A_j; stop when the largest unshot radiosity is below about 1e-12")


SLIPS = {
    "check_jacobi_step": [[2.2, 1.352], [2.1, 1.64], [2.4, 1.4], [0.2, 0.32]],
    "check_gauss_seidel_step": [[1.72, 3.1], [1.744, 3.1], [0.72, 0.172]],
    "check_reciprocity": [0.0384, 0.12, 0.88],
    "check_parallel_form_factor": [0.0686, 1.2732, 0.1998],
    "check_shot": [[0, 1.225, 2.12], [1.5, 1.45, 2.48], [0, 1.9, 2.6]],
}


# Every checker above reads its answer through the shared layer: any object gives a Result.
guard_checkers(globals())
