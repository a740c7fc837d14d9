#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes data/pw85_regression_pairs.txt: the pairs that the fuzzing of issue 25
found wrong, with references at 700 digits (mpmath, gen_geometry.geometry():
safeguarded Newton on f' at the working precision), each rounded once to
a double. Never computed by pw85.

One pair per line: its name, then r12 (3), q1 (6), q2 (6), then μ², λ,
x − c1 (3), n (3), ∂μ²/∂r12 (3), ∂μ²/∂ω1 (3), ∂μ²/∂ω2 (3), all as C99
hexadecimal floats.

    /usr/bin/python3 data/gen_regressions.py   # from the top of the tree
"""
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import gen_geometry as geo  # noqa: E402
import mpmath  # noqa: E402

DPS = 700  # the inputs span 2^1400: 80 digits beyond their range
OUT = HERE / "pw85_regression_pairs.txt"

PAIRS = {
    # μ² wrong by 2.7e-8 (overlap of the wrong sign): the unit sphere and a
    # needle of cond 1e12 about 2^790 times larger.
    "needle-far-larger": (
        ["0x1.a4e4c9af312a3p+376", "-0x1.e2364ab3e346dp+375",
         "-0x1.8ce35158918aap+375"],
        ["1", "0", "0", "1", "0", "1"],
        ["0x1.76cb6155418f5p+785", "0x1.3f0c32f772a1ap+788",
         "0x1.28797696eed27p+788", "0x1.0f9b62362bebcp+791",
         "0x1.f8c8e40165277p+790", "0x1.d51323a4e104ap+790"]),
    # A torque of order 2^-369 returned as 0.
    "torque-underflow": (
        ["-0x1.77516d2c89cffp+326", "0x1.64723be926341p+327",
         "-0x1.77ac8f4963f4fp+326"],
        ["0x1.2f83d3139f8e4p-84", "0x1.7a9dcc03ff873p-85",
         "0x1.afc569cde2f88p-85", "0x1.d84d06b315252p-86",
         "0x1.0d4dd966c1707p-85", "0x1.331cbd88b41e9p-85"],
        ["0x1.82304757a647ep+655", "0x1.da3f3de94e5f6p+600",
         "0x1.6d52735209c4ap+598", "0x1.82304757a647cp+655",
         "0x1.bfc7afb52229ep+600", "0x1.82304757a647cp+655"]),
    # A flat maximum (f''·λ²/μ² = −1.5e-5) with cond Q(λ*) = 2.9.
    "flat-maximum": (
        ["-0x1.9d520234705ddp+50", "-0x1.2071cd36c83fep+50",
         "0x1.4b9f86efe106ep+48"],
        ["0x1.1e358047f982ap+97", "-0x1.7ad087b3d9957p+97",
         "0x1.b3852326e4d84p+95", "0x1.1a5463e46dbf6p+98",
         "0x1.2ff05327bb5ecp+95", "0x1.93976be5225bp+98"],
        ["0x1.18fa520e5b0f4p+101", "0x1.d27dd89adddd4p+100",
         "0x1.385041ff011c4p+100", "0x1.6f5f3214333ddp+101",
         "-0x1.03c8b5e3eb9bcp+100", "0x1.da6cca885319fp+101"]),
    # λ* = 5.9e-66 with cond(Q1) = 3.9e15.
    "lambda-near-zero": (
        ["0x1.0fae96d8aac43p+243", "0x1.b13afb32bd73ep+241",
         "0x1.00ebe2d32a2fbp+242"],
        ["0x1.007f2452c654bp+0", "0x1.114a4d750701fp-4",
         "-0x1.510198ef3735fp+21", "0x1.de345629ca376p+25",
         "-0x1.09d5af2c28577p+22", "0x1.bea3be3a6f023p+51"],
        ["0x1.65904c278cb5cp+529", "-0x1.ec8c1164f28p+527",
         "0x1.406bb29c404c6p+529", "0x1.408c02a5877cep+530",
         "0x1.deea29145686p+527", "0x1.778d8efa9f35ep+529"]),
    # fuzz-contact-structured: λ of the contact function 1.8e-8 off at a
    # maximum flatter still (f''·λ²/μ² = −1.5e-9), cond(Q1) = 9e15.
    "flat-lambda": (
        ["0x1.2b47af9ba1547p-60", "-0x1.e03f029f4b623p-62",
         "-0x1.5f6363ebeba2fp-61"],
        ["0x1.c38e0eb71dcacp-121", "0x1.3bd664e651b5ep-122",
         "0x1.844e0e11e225ap-124", "0x1.8dafe1f2b794bp-123",
         "-0x1.fb3e0c7e217a8p-123", "0x1.d905f8cc344ffp-121"],
        ["0x1.091d7ae4291d7p-120", "0x1.6e4ae764cc3cp-128",
         "-0x1.1dddd57c6945p-126", "0x1.0297cae3dbf26p-120",
         "0x1.10fe37859fe2p-126", "0x1.0c9aba37faf05p-120"]),
    # fuzz-geometry: forms 2^1080 apart, ρ = √(P2/P1) overflowed (ω = +∞
    # everywhere): λ 2^11 times too small, in the contact function and the
    # geometry (μ² right: f is flat there).
    "rho-overflow": (
        ["-0x1.77516d2c89cffp+326", "0x1.696233f926341p+247",
         "0x0.00000f45447bep-1022"],
        ["0x1.2f83d79p-84", "0x1.7a9dcc03ff873p-85", "0x1.afc569cde2f88p-85",
         "0x1.d84d06b315252p-86", "0x1.0d4dd966c4107p-85",
         "0x1.331cbd88b41e9p-85"],
        ["0x1.d3d3d3d3d3d3dp+996", "-0x1.8e82304757a64p+871",
         "0x1.57da3f3de94e5p+167", "0x1.556d52735209cp+967",
         "-0x1.8e82304757a64p-537", "0x1.57bfc7afb5222p+967"]),
    # fuzz-contact-structured: λ 1.1e-8 off at a flat maximum with
    # cond(Q2) = 9.4e15, where the slope test alone did not polish.
    "flat-lambda-ill-conditioned": (
        ["0x1.6f7d60898a1acp+41", "0x1.1843ffe8e4f1cp+38",
         "-0x1.7e1e45cf03b28p+42"],
        ["0x1.ce021f6a50c28p+85", "-0x1.39aeb4098bc7p+74",
         "-0x1.52adf23422944p+84", "0x1.728d5b042a423p+86",
         "0x1.ace0dc9da26b8p+78", "0x1.f0a9546ad5cdep+82"],
        ["0x1.c6bc67a79783bp+85", "-0x1.673c203559208p+85",
         "-0x1.1301f4fead7fcp+82", "0x1.2283e8c8fb2aap+85",
         "-0x1.58f5602dbe81cp+82", "0x1.707fd7c7b6a8fp+86"]),
    # fuzz-contact-raw: a flat maximum (ω′ = 5e-6 at λ* = 0.0075, cond(Qᵢ)
    # near 1e15) where the finish's last secant ran through ω's rounding
    # noise (14.6): the flatness test missed it, and λ was 3e-8 off.
    "flat-secant": (
        ["-0x1.0000100000000p-399", "0x1.747474f180000p+373",
         "0x1.f474747474747p+124"],
        ["0x1.7474747474747p+118", "0x1.7474747474747p+117",
         "0x1.7474747474747p+117", "0x1.7474747474747p+117",
         "0x0.000000000f8f0p-1022", "0x1.7474747478100p+117"],
        ["0x1.7474757475700p+117", "0x1.7474747474347p+117",
         "0x1.7474747474747p+117", "0x1.7474747474747p+117",
         "0x1.7474747474747p+117", "0x1.7474747d84747p+117"]),
    # fuzz-contact-raw: λ* = 8.5e-66 (the lambda-near-zero family,
    # cond(Q1) = 3.9e15), μ² 0.4996 ulp above a double: the finish met
    # ω = 0 exactly and kept stepping in place, then returned the λ of
    # the largest f, 0.9 % off; and the double-double factorisation's
    # error (κ·2⁻¹⁰⁴, an ulp here) rounded μ² the wrong way.
    "omega-zero": (
        ["0x1.0fae96d8aac2cp+243", "0x1.b13afb32bd73ep+241",
         "0x1.00ebe2d34a2fbp+18"],
        ["0x1.007f2452c654bp+0", "0x1.1e53dd750701fp-4",
         "-0x1.510198ef3735fp+21", "0x1.de34a019ca376p+25",
         "-0x1.09d5af2c28577p+22", "0x1.bea3be3a6f023p+51"],
        ["0x1.65904c278cb5cp+529", "-0x1.ec8c1164f2800p+527",
         "0x1.406bb29c404c6p+529", "0x1.408c02a5875cep+530",
         "0x1.deea291456860p+527", "0x1.778d8efa9f35ep+529"]),
    # fuzz-contact-raw: a maximum so flat (ω′ = 6e-14 at λ* = 0.357) that
    # ω rounds to 0 over 2e-3 of λ: the polish refused the step it needed
    # (above polish_max_step), and λ stayed 1.6e-3 off.
    "flat-trust": (
        ["-0x1.02f0100000000p-399", "0x1.cffff4f180000p+385",
         "0x1.f00007ffc2058p+124"],
        ["0x1.7474747474747p+118", "0x1.7474747474747p+117",
         "0x1.7474747474747p+117", "0x1.7474747474767p+117",
         "0x0.07ffd77ecf8f0p-1022", "0x1.7474747474747p+117"],
        ["0x1.74747474747bfp+117", "0x1.7474747474757p+117",
         "0x1.7474747474747p+117", "0x1.7474747474757p+117",
         "0x1.7474747474747p+117", "0x1.7474747474747p+117"]),
    # fuzz-geometry (a campaign after this session's fixes): ω′ = 2.5e-12 at
    # λ* = 0.087, cond(Qᵢ) near 1e15: the polish, with the plain ω′ (a few
    # percent off) as slope, converged linearly and stopped 2.4e-11 off.
    "polish-secant": (
        ["0x1.8cb477fff0000p-264", "-0x1.d4747470000afp-116",
         "0x1.169fe7effffb8p+492"],
        ["0x1.7474747474752p+118", "0x1.7474747474747p+117",
         "0x1.7474747474747p+117", "0x1.7474747474747p+117",
         "0x0.0f000000000f8p-1022", "0x1.7474747474747p+117"],
        ["0x1.7474747474547p+118", "0x1.7474747474747p+117",
         "0x1.7474747472947p+117", "0x1.7474747474747p+117",
         "0x1.7474747474747p+117", "0x1.7474747474d47p+117"]),
    # fuzz-geometry (an 1800 s campaign, seed 26): maxima so flat that the
    # search's λ was 0.6 % and 0.8 % off and the polish's eight steps of
    # at most 1e-3 (relative) fell short: the geometry's λ stayed 4.6e-7
    # and 2.7e-7 off.
    "geo-flat-21e2b386": (
        ["0x1.b78af2f470000p-403", "-0x1.d47474700007fp-116",
         "0x1.025474747b8b8p-903"],
        ["0x1.7474747474747p+118", "0x1.7474747474747p+117",
         "0x1.7474747474747p+117", "0x1.7474747474760p+117",
         "0x1.0f000000001f8p-367", "0x1.7474747474747p+117"],
        ["0x1.7474747474747p+118", "0x1.7474747bf4747p+117",
         "0x1.7474747474747p+117", "0x1.7474747474757p+117",
         "0x1.7474747474747p+117", "0x1.7474747474747p+117"]),
    "geo-flat-89cec286": (
        ["0x1.b78af2f470000p-403", "-0x1.d47474d007b7fp-116",
         "0x1.025474747b8b8p-903"],
        ["0x1.7474747474747p+118", "0x1.7474747474747p+117",
         "0x1.7474747474747p+117", "0x1.747474747474fp+117",
         "0x1.0f000000000f8p-367", "0x1.7474747474747p+117"],
        ["0x1.7474747474747p+118", "-0x1.7474747474747p+117",
         "0x1.7474747474747p+117", "0x1.74747474747c1p+117",
         "0x1.0f000ffffff11p-767", "0x1.7474747474747p+117"]),
    # fuzz-contact-raw (an 1800 s campaign, seed 27): λ* = 1.2e-6 with
    # cond(Q1) = 2.9e15; the plain ω′ (3.7e8) and the last secant (8e5,
    # through ω's rounding noise) both far above the slope (about 1e3), so
    # that the flatness test saw no flat maximum and did not polish: λ of
    # the contact function was 1.2e-8 relative off.
    "flat-least-slope": (
        ["0x1.b7850ca47p-403", "-0x1.d00000001007fp-116",
         "0x1.025474747b8b8p-903"],
        ["0x1.7474747474747p+118", "0x1.7474747474747p+117",
         "0x1.7474747474747p+117", "0x1.747474747476p+117",
         "0x1.0f000000001f8p-367", "0x1.7474747474747p+117"],
        ["0x1.7474747474747p+118", "0x1.7474747bf4747p+117",
         "0x1.7474747474764p+117", "0x1.7578000000147p+117",
         "0x1.7474747674747p+117", "0x1.7474747472047p+117"]),
    # fuzz-contact-raw (an 1800 s campaign, seed 28), far beyond the
    # documented domain (cond(Qi) up to 1e600, subnormal entries): the
    # search's f was NaN; the contact function floored μ² at the sphere
    # bound (0 here), the overlap test's exact stage read NaN as
    # "disjoint", and the two contradicted each other.
    "overlap-nan-19b7f977": (
        ["0x0.03f00002a0000p-1022", "0x1.ff000003fedf0p-1020", "0x0.0000000000038p-1022"],
        ["0x1.f910000000000p-1008", "0x0.000a500000101p-1022", "0x0.3000000000000p-1022", "0x1.ff01fc2860000p-1020", "0x1.ff00000000000p-1020", "0x1.ff00000000000p-1020"],
        ["0x1.fe43c88000000p+1008", "0x1.2860000000000p-515", "0x0.0000000003ff0p-1022", "0x0.03ff003ba3ff0p-1022", "0x0.03ff000000000p-1022", "0x0.03ff00000e400p-1022"]),
    "overlap-nan-525e09ed": (
        ["0x0.0000190000000p-1022", "0x1.ffa0100004000p-1008", "0x1.fffffffffffffp-1014"],
        ["0x1.76a0400000000p+6", "0x0.000a5000001d8p-1022", "0x0.0p+0", "0x0.03ff0c2860000p-1022", "0x0.03ff008000000p-1022", "0x0.03ff000000000p-1022"],
        ["0x1.fe43c8800007ap+1008", "0x0.0p+0", "0x0.0p+0", "0x0.03ff01f000000p-1022", "0x0.03ff008020000p-1022", "0x0.03ff000000000p-1022"]),
    "overlap-nan-93999427": (
        ["0x1.0406000010000p-879", "0x0.000000010f221p-1022", "-0x1.00c4000000000p-415"],
        ["0x1.f91e03d000007p-1008", "0x0.000a500000100p-1022", "0x0.0p+0", "0x1.ff01fc2860000p-1020", "0x1.ff00000000000p-1020", "0x1.ff00000000000p-1020"],
        ["0x1.fe43c88000000p+1008", "0x0.0p+0", "0x0.0p+0", "0x0.03ff01fc28600p-1022", "0x0.03ff000000000p-1022", "0x0.03ff000000000p-1022"]),
    "overlap-nan-9c43c26d": (
        ["0x1.52f010001fc00p-1017", "0x1.cffff00004aa6p-991", "0x1.7bf00a3fc2058p-1019"],
        ["0x1.7474747474747p+118", "0x1.7474747474747p+117", "0x1.7474747474747p+117", "0x1.7474747474747p+117", "0x1.0810284130710p-879", "0x1.7474747474747p+117"],
        ["0x1.7474747474747p+118", "0x1.7474747474747p+117", "0x1.7474747474747p+117", "0x1.7474747474747p+117", "0x1.f8102883f0710p-864", "0x1.7474747474747p+117"]),
    "overlap-nan-bf7460f8": (
        ["0x0.000000000003ep-1022", "0x0.0000000100000p-1022", "0x0.0000000003e00p-1022"],
        ["0x1.f910000000000p-1008", "0x0.000a500000101p-1022", "0x0.3000000000000p-1022", "0x1.ff01fc2860000p-1020", "0x1.ff00000002e00p-1020", "0x1.ff00000000000p-1020"],
        ["0x1.fe43c88000000p+1008", "0x0.0040000000000p-1022", "0x0.0000000002d00p-1022", "0x1.ff01fc2860000p-1020", "0x1.ff00000000000p-1020", "0x1.ff00000000000p-1020"]),
    # fuzz-geometry (a 1502 s campaign, seed 12): forms spanning the range
    # of a double, λ* far below 2^-60 or near 1 with a flat maximum. The
    # compensated finish stopped on a secant through a far point (μ² 3.5
    # to 114 ulps off on finish-973e0d48, -b75ab5eb, -f7be7871) or on a
    # fallback step that underflowed (λ up to 2^800 times λ*).
    "finish-0b25ad67": (
        ["0x1.7848000006d00p+117", "-0x1.747474f474747p-123",
         "0x1.5b8b8b9474747p+124"],
        ["0x1.747474747bf4dp+117", "0x1.7474747474747p+117",
         "0x1.747474700a547p+117", "0x1.6474747474747p+121",
         "0x1.7474747474747p+117", "0x1.757ff48003e00p+117"],
        ["0x1.747474747bf44p+117", "0x1.7474747474747p+117",
         "0x1.7474747474747p+117", "0x1.7474747474247p+117",
         "0x1.7474747474747p+117", "0x1.f7c48003f0047p+128"]),
    "finish-0d4c34d1": (
        ["0x1.a4e4c9af312a3p+376", "0x0.03ff0003e346dp-1022",
         "0x0.03ff0008d0031p-1022"],
        ["0x1.f0000d3f00f04p-1021", "0x0.005000024f000p-1022",
         "0x0.00000001ff000p-1022", "0x0.07ffdc7b62541p-1022",
         "0x0.0070400010036p-1022", "0x0.03f19000000f0p-1022"],
        ["0x1.76cb615540426p+785", "0x1.3f0c32f772a1ap+788",
         "0x1.28797696eed27p+788", "0x1.0f9b62362bebcp+791",
         "0x1.f8c8e40165277p+790", "0x1.d51323a4e104ap+790"]),
    "finish-0e3138d9": (
        ["0x1.0f00000000000p-15", "0x0.0000000100000p-1022",
         "-0x1.bf8bd00000000p+326"],
        ["0x1.56e1f00007fffp-997", "0x0.0p+0", "0x0.0p+0",
         "0x1.ff01fc2f8f359p-1020", "0x1.ff00000000000p-1020",
         "0x1.ff00000000000p-1020"],
        ["0x1.7e43c88000000p+996", "0x0.0p+0", "0x0.0p+0",
         "0x1.7e43c88007500p+996", "0x1.0000000000000p-1019",
         "0x1.7e43c8800759cp+996"]),
    "finish-122a3c67": (
        ["-0x1.d3eb0c68d3eb0p+729", "-0x1.ffe4f390bffb5p-1008",
         "0x0.03268b4865003p-1022"],
        ["0x0.01fc2f8f35900p-1022", "0x0.00000006ea501p-1022",
         "0x0.0000000b00000p-1022", "0x0.00001f3590000p-1022",
         "0x0.0000016000000p-1022", "0x1.ffd56ef2be100p-1016"],
        ["0x1.c6c6c6c6c6c00p+711", "0x1.c6c6c6c6c6c6cp-1001",
         "0x1.c6c6c6c6c6c07p+711", "0x1.c6c6c6c6c6c6cp+711",
         "0x0.02955ffff6c6cp-1022", "0x1.c6c6c6c6c6c6cp+711"]),
    "finish-260f865d": (
        ["-0x1.d3eb0c68d3eb0p+729", "-0x1.ffe4f390bffb5p-1008",
         "0x0.03268b4865003p-1022"],
        ["0x0.01fc2f8f35900p-1022", "0x0.00000006ea501p-1022",
         "0x0.0b00000000000p-1022", "0x1.3590000000000p-992",
         "0x1.6000000000000p-1022", "0x0.6010000000000p-1022"],
        ["0x1.c6c6c6c6c6c7cp+711", "0x1.16c6c6c6c6c6cp-911",
         "0x1.c6c6c6c6c6c6cp+711", "0x1.c6c6c6c6c6c7cp+711",
         "0x1.16c6c6c6c6c6cp-911", "0x1.c6c6c6c6c6c6cp+711"]),
    "finish-2b99b203": (
        ["-0x1.0f00000000000p+17", "0x0.00000001000ffp-1022", "0x0.0p+0"],
        ["0x1.56e1fc2f8f359p-997", "0x0.0p+0", "0x0.0p+0",
         "0x1.ff01fc2f8f359p-1020", "0x1.ff00000000000p-1020",
         "0x1.ff00000000000p-1020"],
        ["0x1.7e43c88000000p+996", "0x0.0p+0", "0x0.0p+0",
         "0x1.7e43088007500p+996", "0x1.0000000000000p-1019",
         "0x1.7e43c8800759cp+996"]),
    "finish-2cb368cf": (
        ["-0x1.f0e0000000000p+16", "0x0.00000001000ffp-1022", "0x0.0p+0"],
        ["0x1.56e1fc2f8f359p-997", "0x0.0p+0", "0x0.0p+0",
         "0x1.ff01fc2f8f359p-1020", "0x1.ff00000000000p-1020",
         "0x1.ff00000000000p-1020"],
        ["0x1.7e43c88000000p+996", "0x0.0p+0", "0x0.0p+0",
         "0x1.7e43c88007500p+996", "0x1.0000000000000p-1019",
         "0x1.7e43c8800759cp+996"]),
    "finish-32447514": (
        ["0x1.0f0003b000000p-15", "0x0.0000000100000p-1022",
         "0x1.1cf2b66000000p+748"],
        ["0x1.0007fffb1cf2bp-1007", "0x0.0p+0", "0x0.0p+0",
         "0x1.ff01fc2f8f359p-1020", "0x1.ff00000000000p-1020",
         "0x1.ff00000000000p-1020"],
        ["0x1.7e43c88000000p+996", "0x0.0p+0", "0x0.0p+0",
         "0x1.7e43c88007500p+996", "0x1.0000000000000p-1019",
         "0x1.7e43c8800759cp+996"]),
    "finish-4a19b1ac": (
        ["-0x1.0000100000000p-399", "0x1.747474f180000p+117",
         "0x1.f474747474747p+124"],
        ["0x1.7474747474747p+118", "0x1.7474747474747p+117",
         "0x1.7474747474747p+117", "0x1.7474747474747p+117",
         "0x1.7474747474747p+117", "0x1.747ff48003e00p+117"],
        ["0x1.74747474747bfp+117", "0x1.7474747470051p+117",
         "0x1.7474747474747p+117", "0x1.7474747474747p+117",
         "0x1.747470000005cp+117", "0x1.03e0047474747p+129"]),
    "finish-53461f9f": (
        ["-0x1.d3eb0c63e8db0p+729", "-0x1.ffe4f340bffb5p-1008",
         "0x0.1ffff4c865003p-1022"],
        ["0x1.f3eeac36bfd7fp-1022", "0x0.000006ea50100p-1022",
         "0x1.90000b0000000p-1018", "0x0.001f300000000p-1022",
         "0x0.0001600000000p-1022", "0x1.c6c0000000601p-1001"],
        ["0x1.c6c6c6c6c7c64p+711", "0x1.c6c6c6c6c6c6cp-1001",
         "0x1.c6c6c6c6c6c07p+711", "0x1.c6ceb6cde6c6cp+711",
         "0x1.955ffff6c6c6cp-1021", "0x1.c6c6c6c6c6c00p+711"]),
    "finish-5e911da4": (
        ["0x1.8fdff40008db0p-1008", "-0x1.ffe4f340bff59p-1008",
         "0x1.c6c6c6c6caffdp+711"],
        ["0x0.01fc2bef6c06cp-1022", "0x0.00000006ea501p-1022",
         "0x0.0590000b00000p-1022", "0x0.00001f3000000p-1022",
         "0x0.0000016000000p-1022", "0x1.4696c06010000p-1017"],
        ["0x1.c6c6c6c6c6c7cp+711", "0x1.16c6c6c6c6c6cp-911",
         "0x1.c6c6c6c6c6c6cp+711", "0x1.c6c6ceb6cde6cp+711",
         "0x0.02955ffff6c6cp-1022", "0x1.c6c6c6c6c906cp+711"]),
    "finish-66c1d4ef": (
        ["0x1.0f00000000000p-15", "0x0.0000000100000p-1022",
         "-0x1.0000000000000p+881"],
        ["0x1.f91e03d070ca6p-1008", "0x0.000a500000100p-1022", "0x0.0p+0",
         "0x1.ff01fc2f8f359p-1020", "0x1.ff00000000000p-1020",
         "0x1.ff00000000000p-1020"],
        ["0x1.3e43c88000000p+996", "0x0.0p+0", "0x0.0p+0",
         "0x1.7e43c88007500p+996", "0x1.0000000000000p-1019",
         "0x1.7e43c8800759cp+996"]),
    "finish-8e68adb9": (
        ["-0x1.0f00000000000p+97", "0x0.0000000100000p-1022", "0x0.0p+0"],
        ["0x1.56e1fc2f8f359p-997", "0x0.0p+0", "0x0.0p+0",
         "0x1.ff01fc2f8f359p-1020", "0x1.ff00000000000p-1020",
         "0x1.ff00000000000p-1020"],
        ["0x1.7e43c88000000p+996", "0x0.0p+0", "0x0.0p+0",
         "0x1.7e43c88007500p+996", "0x1.0000000000000p-1019",
         "0x1.7e43c8800759cp+996"]),
    "finish-973e0d48": (
        ["-0x1.f754f00000400p-858", "-0x1.7000000007ffcp+94",
         "0x0.0b70000000000p-1022"],
        ["0x1.7474746474747p+117", "0x0.0003f1f000047p-1022",
         "0x0.079000000009bp-1022", "0x1.7474747474759p+117",
         "0x1.7474747474747p+117", "0x1.7474747474747p+117"],
        ["0x1.7474747474747p+117", "0x1.7474747574747p+117",
         "0x1.7474747474747p-699", "0x1.7474747ff5dfep+117",
         "0x1.78e00e06b3631p-208", "0x1.74747000003f8p+117"]),
    "finish-b75ab5eb": (
        ["-0x1.0000100000000p-399", "0x1.cffff4f180000p+385",
         "0x1.f00007ffc2058p+124"],
        ["0x1.7474747474747p+118", "0x1.7474747474747p+117",
         "0x1.7474747474747p+117", "0x1.7474747474767p+117",
         "0x0.07ffd77ecf8f0p-1022", "0x1.7474747474747p+117"],
        ["0x1.74747474747bfp+117", "0x1.7474747474757p+117",
         "0x1.7474747474747p+117", "0x1.747474d476747p+117",
         "0x1.7474747474747p+117", "0x1.7474747474747p+117"]),
    "finish-c49a059a": (
        ["0x1.0f00000000000p-15", "0x0.0000000100000p-1022",
         "-0x1.9000000000000p+902"],
        ["0x1.56e1fc200f300p-997", "0x0.0p+0", "0x0.0p+0",
         "0x1.ff01fc2f8f359p-1020", "0x1.ff00000000000p-1020",
         "0x1.ff00000000000p-1020"],
        ["0x1.7e43c88000000p+996", "0x0.0p+0", "0x0.0p+0",
         "0x1.7e43c88007500p+996", "0x1.0000000000000p-1019",
         "0x1.7e43c8800759cp+996"]),
    "finish-c54a72b5": (
        ["-0x1.0000100000000p-399", "0x1.747474f180000p+117",
         "0x1.f474747474747p+124"],
        ["0x1.7474747474747p+118", "0x1.7474747474747p+117",
         "0x1.7474747474747p+117", "0x1.7474747474747p+117",
         "0x1.7474747474747p+117", "0x1.747ff48003e00p+117"],
        ["0x1.74747474747bfp+117", "0x1.7474747472947p+117",
         "0x1.7474747474747p+117", "0x1.7474747474747p+117",
         "0x1.7474747474747p+117", "0x1.f48003e004747p+128"]),
    "finish-c867048c": (
        ["0x1.0f00000000000p-15", "-0x1.0000000100000p+1009", "0x0.0p+0"],
        ["0x1.56e1fc2f8f359p-997", "0x0.0p+0", "0x0.0p+0",
         "0x1.ff01fc2f8f359p-1020", "0x1.ff00000000000p-1020",
         "0x1.ff00000000000p-1020"],
        ["0x1.7e43c88000000p+996", "0x0.0p+0", "0x0.0p+0",
         "0x1.7e43c88007500p+996", "0x1.0000000000000p-1019",
         "0x1.7e43c8800759cp+996"]),
    "finish-ec1a0ddd": (
        ["-0x1.d3eb0c68d3eb0p+729", "-0x1.ffe4f390bffb5p-1008",
         "0x0.03268b4865003p-1022"],
        ["0x0.01fc2f8f35900p-1022", "0x0.00000006ea501p-1022",
         "0x0.0000000b00000p-1022", "0x0.1f35900630000p-1022",
         "0x0.0160000000000p-1022", "0x1.c6c0001000000p-1017"],
        ["0x1.c6c6c6c7c6c06p+711", "0x1.c6c6c6c6c6c6cp+711",
         "0x1.c6c6c6c6c0701p+711", "0x1.c6c6c6c7c6c6cp+711",
         "0x1.c6c6c6c6c6c6cp+711", "0x1.c6c6c6c6c0701p+711"]),
    "finish-f7be7871": (
        ["-0x1.0000100000000p-399", "0x1.747474f180000p+373",
         "0x1.f474747474747p+124"],
        ["0x1.7474747474747p+118", "0x1.7474747474747p+117",
         "0x1.7474747474747p+117", "0x1.7474747474747p+117",
         "0x0.000000000f8f0p-1022", "0x1.7474747478100p+117"],
        ["0x1.7474747475700p+117", "0x1.7474747474747p+117",
         "0x1.7474747474747p+117", "0x1.7474747474747p+117",
         "0x1.7474747474747p+117", "0x1.7474747d84747p+117"]),
    # fuzz-geometry (seed 33): λ* = 1.0e-3 where the search's orientation
    # (the sphere model) put it near 1: the polish's λ carried 5e-14 of
    # it relative, and x − c1 was 14·u·cond(Q(λ)) off.
    "point-orientation": (
        ["0x1.0474747006d00p+113", "-0x1.747474f478084p-123", "0x1.5b8b8b9474747p+124"],
        ["0x1.747474747bf4dp+117", "0x1.7474747474747p+117", "0x1.747474700a547p+117", "0x1.6474747474747p+121", "0x1.7474747474747p+117", "0x1.757ff48003e00p+117"],
        ["0x1.747474747bf44p+117", "0x1.7474747474747p+117", "0x1.7474747474747p+117", "0x1.7474747474247p+117", "0x1.7474747474747p+117", "0x1.f7c48003f0047p+128"]),
    # fuzz-contact-raw (seed 28): the diagonals of q1 and q2 span 2^2028
    # to 2^2045 (binary exponents), λ* near 2^-1008; μ² was 1 to 2 ulps
    # off (the compensated finish's low parts subnormal). Beyond the span
    # that the search carries since 2.5.0: PW85_ERANGE.
    "span-4cbb6b91": (
        ["-0x1.8092000800000p+3", "0x1.000ffffefffffp-223", "0x1.5000000000000p-1019"],
        ["0x1.f910000000000p-1008", "0x1.b00a500000101p-1018", "0x0.0p+0", "0x1.effe43c880000p-1016", "0x1.0000000000000p-1021", "0x1.ff00000000000p-1020"],
        ["0x1.fe43c88006401p+1008", "0x0.0p+0", "0x0.0000000002d00p-1022", "0x1.7008800750000p+996", "0x1.000fc00000100p-1019", "0x1.7e43c8800759cp+996"]),
    "span-b83adeb9": (
        ["0x1.0f00000000000p-15", "0x0.0000000100000p-1022", "-0x1.0000000000000p+817"],
        ["0x1.f91e03d070ca4p-1008", "0x0.000a500000100p-1022", "0x0.0000000000400p-1022", "0x0.0000004f8f359p-1022", "0x0.0p+0", "0x1.ff00000000000p-1020"],
        ["0x1.3e43c88000028p+996", "0x0.0020000000000p-1022", "0x0.0p+0", "0x1.6e43c92007500p+996", "0x1.0000000000000p-1019", "0x1.7e43c8800759cp+996"]),
    "span-c9f92fa5": (
        ["-0x1.8090000800000p+3", "0x0.000ffffefffffp-1022", "0x1.5000000000000p-1019"],
        ["0x1.100ff91000000p-1007", "0x0.0000000a50000p-1022", "0x0.0p+0", "0x0.0003ff01fc286p-1022", "0x0.0003ff0000000p-1022", "0x0.0003ff0000000p-1022"],
        ["0x1.fe43c88000000p+1008", "0x0.0p+0", "0x0.0000000002d00p-1022", "0x1.4000000000000p+996", "0x1.0000000000000p-1019", "0x1.7e43c8800759cp+996"]),
    # fuzz-contact-raw (seed 29): forms singular far below double
    # precision: the contact function answers PW85_ERANGE (f not
    # evaluable along its search), the overlap test PW85_SUCCESS, +1 from
    # the sphere bound alone (3.7e24 here; pw85.h's one exception).
    "overlap-sphere-erange": (
        ["0x0.02f01ff01fc00p-1022", "0x1.fff0400009700p-989", "0x1.7bf0040fc2158p+101"],
        ["0x1.7474747474747p+118", "0x1.7474747474747p+117", "0x1.7474747474747p+117", "0x1.7474747474747p+117", "0x1.00007c8130710p-879", "0x1.7474747474747p+117"],
        ["0x1.7474747474747p+118", "0x1.7474747474747p+117", "0x1.7474747474747p+117", "0x1.7474747474747p+117", "0x1.f81f6263f0710p-864", "0x1.7474747474747p+117"]),
    # fuzz-geometry (seed 29): 1 − λ* = 6.66e-155, the forms 2^997 apart,
    # q2 nearly of rank one (cond 1e10): the Newton step's ρ′ overflowed
    # (aᵢ ~ 2^1039) where λρ′ does not, so the polish stopped at the
    # search's λ, 8.8e-13 off relative in 1 − λ, and ∂μ²/∂ω2 (which scales
    # as 1/(1 − λ) here) 1.5e-12 of its scale off.
    "newton-overflow": (
        ["-0x1.b2e0100003800p-112", "0x1.cc07921effe7fp-991", "0x1.7bf00a2fc2058p-1019"],
        ["0x1.7474747474747p+118", "0x1.7474747474747p+117", "-0x1.a704747474747p-45", "0x1.74700007fff9cp+117", "0x1.0810284130710p-879", "0x1.7474747474747p+117"],
        ["0x1.90909094747e0p-879", "0x1.9090909090909p-879", "0x1.9090909090909p-879", "0x1.9090909090909p-879", "0x1.9090909090909p-879", "0x1.9093f09000009p-879"]),
    # A held-out set of the hard set's lambda_end_ill class (issue 13's
    # recipe, another seed): λ* = 3.7e-10, cond(Q1) = 1.1e15,
    # cond(Q2) = 8.6e15 = cond(Q(λ*)). The double-double finish's residual
    # used Q(λ) as hi + lo, 2.4e-18 relative off in f here: μ² lies 0.517
    # of an ulp above a double, and was rounded down.
    "residual-q-exact": (
        ["-0x1.667ef88a64d63p-11", "0x1.8741bc61a662fp-13", "0x1.3b84c0dfa7f7ap-7"],
        ["0x1.74c0ce4c8e922p-82", "-0x1.2f856cf297ea4p-80", "0x1.27ae84574b024p-82", "0x1.ee4baa875c1c3p-79", "-0x1.e1875736b1001p-81", "0x1.d5176e5a03c93p-83"],
        ["0x1.b14b3f22fba36p+34", "0x1.82ff451855788p+33", "-0x1.614fcc3344732p+33", "0x1.bad6efd25c6ffp+32", "-0x1.8d51b1820baf4p+32", "0x1.64de5030fef29p+32"]),
    # fuzz-geometry (campaign of 2026-11-29, seed 20261129): λ* = 9.7e-165
    # with Q1 nearly singular (every entry within 5e-5 of 2^-927·1.38,
    # cond 2.6e14) and cond(Q(λ*)) = 6.2 (mpmath). The plain ω had the wrong
    # sign at the search's λ, and its ω′ was 0.2 % off; the polish accepted
    # its first step (1.6e-10 relative) with that slope, leaving λ, hence
    # x − c1 (which moves with λ here), 3e-13 off: 440·u·cond(Q(λ)) where
    # pw85.h states 1.5·u·cond(Q(λ)).
    "geo-plain-slope": (
        ["-0x1p-399", "-0x1.1fe7fp+280", "0x1.f4747474742cbp+124"],
        ["0x1.6064747474747p-927", "0x1.6060606060606p-927", "0x1.6060606060606p-927", "0x1.606060606065bp-927", "0x1.6060606060606p-927", "0x1.606060606064p-927"],
        ["0x1.7474747474747p+117", "0x0.000f8f0474747p-1022", "0x0.07ffe71d1cb4p-1022", "0x1.7474747ffp+119", "0x1.7474747474747p+117", "0x1.7474700000064p+117"]),
}


def main():
    lines = ["# Generated by data/gen_regressions.py: name, r12, q1, q2, mu2, "
             "lambda, point, normal, d_r12, d_rot1, d_rot2 (hex)."]
    for name, (r, q1, q2) in PAIRS.items():
        r, q1, q2 = ([float.fromhex(x) for x in v] for v in (r, q1, q2))
        with mpmath.workdps(DPS):
            g = geo.geometry(r, q1, q2, DPS)
            # The torques again, without geometry()'s zeroing of entries
            # small beside the lever arm of both ellipsoids (one torque may
            # be 2^-300 times the other, and is then not noise).
            lam, oml, s = g["lambda"], g["one_minus_lambda"], g["s"]
            Q1, Q2 = geo.mpf_list(q1), geo.mpf_list(q2)
            rot1 = [2 * lam * oml * oml * t
                    for t in geo.cross(s, geo.sym_mv(Q1, s))]
            rot2 = [2 * lam * lam * oml * t
                    for t in geo.cross(s, geo.sym_mv(Q2, s))]
            vals = [g["mu2"], g["lambda"]] + g["point"] + g["normal"] + \
                g["d_r12"] + rot1 + rot2
        fields = [name] + [float.hex(x) for x in r + q1 + q2] + \
            [float.hex(float(v)) for v in vals]
        lines.append(" ".join(fields))
        print(name, float(g["mu2"]), float(g["lambda"]), file=sys.stderr)
    OUT.write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
