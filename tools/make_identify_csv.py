#!/usr/bin/env python3
"""Writes testdata/identify/planar_arm.csv, the recording of tests/identify_cli_test.cc.

The planar two-link arm of Spong, Hutchinson and Vidyasagar, "Robot Modeling and Control" (2006),
section 7.4 (its closed-form equations of motion, written out below: an independent computation,
not massprops' RNEA), in the x-z plane with gravity -z: both joints turn about -y (so a positive
angle raises the link toward +z, as Spong's angles are measured from the x axis). The true arm
(TRUE below) differs from testdata/identify/planar_arm.urdf (the file's values, the prior), and
each joint has viscous friction. Noise: Gaussian, sigma 0.01 N·m, random.Random(51).

Run from the repository root:  python3 tools/make_identify_csv.py > testdata/identify/planar_arm.csv
"""
import math
import random

G = 9.81
# True arm: masses (kg), link length l1, COM distances lc (m), central inertias about y (kg·m²).
TRUE = dict(m1=2.3, m2=1.0, l1=0.5, lc1=0.22, lc2=0.24, I1=0.05, I2=0.012, fv1=0.3, fv2=0.1)
SAMPLES, RATE, SIGMA = 800, 100.0, 0.01


def trajectory(t, j):
    """q, dq, ddq of joint j: a sum of three sinusoids (0.2, 0.4, 0.6 Hz)."""
    q = dq = ddq = 0.0
    for h in (1, 2, 3):
        w = 2 * math.pi * 0.2 * h
        a = 0.9 / h
        phase = 0.7 * j + 1.3 * h * j + 0.4 * h
        q += a * math.sin(w * t + phase)
        dq += a * w * math.cos(w * t + phase)
        ddq -= a * w * w * math.sin(w * t + phase)
    return q, dq, ddq


def torques(q1, q2, dq1, dq2, ddq1, ddq2, p):
    """Spong et al. (2006), section 7.4, plus viscous friction."""
    m1, m2, l1, lc1, lc2, I1, I2 = (p[k] for k in ("m1", "m2", "l1", "lc1", "lc2", "I1", "I2"))
    d11 = m1 * lc1**2 + m2 * (l1**2 + lc2**2 + 2 * l1 * lc2 * math.cos(q2)) + I1 + I2
    d12 = m2 * (lc2**2 + l1 * lc2 * math.cos(q2)) + I2
    d22 = m2 * lc2**2 + I2
    h = -m2 * l1 * lc2 * math.sin(q2)
    phi1 = (m1 * lc1 + m2 * l1) * G * math.cos(q1) + m2 * lc2 * G * math.cos(q1 + q2)
    phi2 = m2 * lc2 * G * math.cos(q1 + q2)
    tau1 = d11 * ddq1 + d12 * ddq2 + 2 * h * dq1 * dq2 + h * dq2**2 + phi1 + p["fv1"] * dq1
    tau2 = d12 * ddq1 + d22 * ddq2 - h * dq1**2 + phi2 + p["fv2"] * dq2
    return tau1, tau2


def main():
    rng = random.Random(51)
    print("# " + " ".join(f"{k}={v}" for k, v in TRUE.items()) + f"; noise sigma {SIGMA}")
    print("time,shoulder.q,shoulder.dq,shoulder.ddq,shoulder.tau,elbow.q,elbow.dq,elbow.ddq,elbow.tau")
    for k in range(SAMPLES):
        t = k / RATE
        q1, dq1, ddq1 = trajectory(t, 0)
        q2, dq2, ddq2 = trajectory(t, 1)
        tau1, tau2 = torques(q1, q2, dq1, dq2, ddq1, ddq2, TRUE)
        tau1 += rng.gauss(0, SIGMA)
        tau2 += rng.gauss(0, SIGMA)
        row = [t, q1, dq1, ddq1, tau1, q2, dq2, ddq2, tau2]
        print(",".join(f"{x:.10g}" for x in row))


if __name__ == "__main__":
    main()
