"""The Jeffcott rotor of tests/rotors.py with one bearing at its disk instead of its damper,
shared by the closed-form tests of bearing reactions, spin-up, modes and the run-up."""

from __future__ import annotations

import numpy as np
from rotors import jeffcott_text

from flexshaft.assembly import build_model
from flexshaft.design import loads_design

KB, CV, CW = 4.0e5, 150.0, 900.0  # contact bearing [N/m], its v and w damping [N s/m]
KI, KP, KD, KS = 100.0, 5.0e3, 2.0, 2.0e5  # N/A, A/m, A s/m, N/m: law 1e2 (5e3 + 2 iΩ) − 2e5
K_INT = 3.0e4  # A/(m s): the PID bearing's integral gain
U = 1e-4  # kg m


def model_with(bearing: str):
    """The Jeffcott rotor with ``bearing`` (TOML keys) at the disk instead of its damper."""
    text = jeffcott_text(0.0, 0.0, elements=4)
    head, tail = text.split("[[bearings]]")
    tail = tail[tail.index("[[disks]]") :]
    return build_model(loads_design(f'{head}[[bearings]]\nname = "b"\nx = 0.5\n{bearing}\n{tail}'))


CONTACT = f'kind = "contact"\nstiffness = {{ v = {KB}, w = {KB} }}\ndamping = {{ v = {CV}, w = {CW} }}'
ACTIVE = f'kind = "active"\nkp = {KP}\nkd = {KD}\nks = {KS}\nki = {KI}'
PID = f'kind = "active"\nkp = {KP}\nkd = {KD}\nintegral_gain = {K_INT}\nks = {KS}\nki = {KI}'


def disk(model):
    node = model.dofs.node_at("shaft", 0.5)
    return model.dofs.shaft(node, "v"), model.dofs.shaft(node, "w")


def imbalance_vector(model, scale: float = 1.0):
    q1 = np.zeros(model.dofs.size, complex)
    v, w = disk(model)
    q1[v], q1[w] = scale * U, -1j * scale * U
    return q1


def major_semi_axis(a: complex, b: complex) -> float:
    """Largest √(Re(a e^{iφ})² + Re(b e^{iφ})²) over 20 000 phases (1e-8 relative)."""
    e = np.exp(1j * np.linspace(0.0, 2 * np.pi, 20000, endpoint=False))
    return float(np.sqrt((a * e).real ** 2 + (b * e).real ** 2).max())


def active_law(omega):
    return KI * (KP + 1j * omega * KD) - KS
