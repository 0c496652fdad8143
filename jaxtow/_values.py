"""The Barge 2 data of the thesis and the documented estimates for what its text lacks: the
one place for these values (the docstring of `jaxtow.presets` gives the reasoning of each
estimate). Plain Python values only; the builders that turn them into models are in
`jaxtow.presets._barge2`. The module sits below every layer, so that the numerical packages
(`jaxtow.strip`) read their defaults from here too."""

from __future__ import annotations

#: Main particulars of Barge 2 (thesis section 3.5; L and B from the text).
BARGE2_LENGTH = 76.2  # m
BARGE2_BREADTH = 24.4  # m
#: Tug speed used throughout thesis chapter 6.
U_TUG_DEFAULT = 2.0  # m/s

#: The documented estimates for values the thesis text lacks (see module docstring).
ASSUMPTIONS = {
    "draft": dict(
        value=5.0,
        units="m",
        note="loaded draft of a 76.2 m x 24.4 m deck barge; estimate, not from the thesis",
    ),
    "a11_over_m": dict(
        value=0.05, units="-", note="surge added mass 5 % of mass (Brix 1993); estimate"
    ),
    "a22,a66": dict(
        value=None,
        units="-",
        note="Clarke, Gedling & Hine (1983) regressions with C_B from m' and T = 5.0 m; estimate",
    ),
    "EA": dict(
        value=2.6e8,
        units="N",
        note="76 mm 6-strand IWRC steel wire, EA = 1.0e11 Pa x 2.63e-3 m^2; estimate",
    ),
    "rake": dict(
        value=None,
        units="m",
        note="Barge 2 bow/stern rake from waterline to keel over a = (1 - C_B) L = 5.49 m "
        "(C_B = 0.928 from m'); geometry estimate, not from the thesis",
    ),
    "wind_table": dict(
        value=None,
        units="-",
        note="ILLUSTRATIVE Barge 2 wind coefficients (BARGE2_WIND_TABLE): OCIMF-form curve "
        "shapes with values chosen by jaxtow; not measured, not the thesis's "
        "(unpublished) Smit Barge 2 table",
    ),
    "cog_z": dict(
        value=10.0,
        units="m",
        note="height of the CoG above the keel for the panel computations (thesis Table B.3, "
        "Barge 1; the thesis's choice after its CoG study, appendix B.3)",
    ),
    "radii_of_gyration": dict(
        value=(0.35, 0.25, 0.25),
        units="B, L, L",
        note="k_xx = 0.35 B, k_yy = k_zz = 0.25 L: the middle of Journee's ranges "
        "(0.30-0.40 B, 0.22-0.28 L; Journee & Massie, Offshore Hydromechanics, "
        "2001), which thesis Table B.1 quotes (the table itself is lost); estimate",
    ),
    "roll_damping": dict(
        value=0.05,
        units="of critical",
        note="linearised viscous roll damping for the panel-method RAOs (potential flow "
        "alone gives an unbounded roll resonance); 5 % of critical, a usual value "
        "for a barge without bilge keels; estimate",
    ),
    "tug_efficiency": dict(
        value=0.75,
        units="-",
        note="offshore towing efficiency 0.75: the usual share of the rated continuous "
        "bollard pull a tug gives at sea; GL Noble Denton 0030 and DNV-ST-N001 tabulate it "
        "against the bollard pull and Hs, a table that was not available to this project: "
        "set [tug] efficiency (or a sea state's tug_efficiency) from the edition in use; "
        "estimate",
    ),
    "wind_height": dict(
        value=10.0,
        units="m",
        note="ILLUSTRATIVE above-water height of Barge 2 with deck cargo (about 1.1 m "
        "freeboard + 9 m cargo); the thesis's 'arbitrary deck load' is not given",
    ),
    "fishtail_yaw_amplitude": dict(
        value=10.0,
        units="deg",
        note="a run fishtails when its yaw amplitude (half the peak-to-peak heading after the "
        "start-up) exceeds 10 deg: the slow drift and gusts swing a course-stable tow by a "
        "few degrees, Barge 2a's calm-water limit cycle by tens of degrees. No guideline "
        "states a number; the risk result carries the one used and is shown at 5 and 20 deg "
        "too; estimate",
    ),
    "risk_initial_yaw": dict(
        value=2.0,
        units="deg",
        note="each Monte Carlo run starts at the static straight-behind equilibrium with a "
        "heading drawn uniformly within +-2 deg, so that an unstable equilibrium is left "
        "even in calm water; estimate",
    ),
    "risk_transient": dict(
        value=600.0,
        units="s",
        note="the first 10 minutes of each run (the start-up of the forces) are left out of "
        "its statistics; estimate",
    ),
    "slack_fraction": dict(
        value=0.05,
        units="of the static tension",
        note="a slack (snatch) event is the towline tension falling below 5 % of its static "
        "value; estimate",
    ),
    "gust_mean_wind": dict(
        value=1.0,
        units="h",
        note="the gust spectrum (NPD, ISO 19901-1) is about the one-hour mean wind at 10 m: a "
        "sea state's wind_speed is taken as that mean, with the gusts on top (conservative "
        "when the given speed is a shorter average); estimate",
    ),
}

#: Plausible ranges of the documented estimates, for the attribution of claims
#: (`jaxtow.studies.attribute`): absolute ends for draft, CoG height, radii of gyration and
#: roll damping; factors on the estimate for a11', a22', a66' and EA'.
PLAUSIBLE_RANGES = {
    "draft": dict(
        low=4.0,
        high=5.5,
        units="m",
        note="loaded draft of a 250 ft deck barge: 4-5 m, 5.5 m deep-loaded",
    ),
    "a11": dict(
        low=0.4,
        high=2.0,
        units="x estimate",
        note="surge added mass 2-10 % of the mass (Brix 1993)",
    ),
    "a22": dict(
        low=0.7,
        high=1.3,
        units="x estimate",
        note="scatter of the Clarke, Gedling & Hine (1983) regression, about +-30 % for a barge",
    ),
    "a66": dict(
        low=0.7,
        high=1.3,
        units="x estimate",
        note="scatter of the Clarke, Gedling & Hine (1983) regression, about +-30 % for a barge",
    ),
    "EA": dict(
        low=0.5,
        high=1.5,
        units="x estimate",
        note="rope modulus 0.8-1.2e11 Pa and 64-88 mm wires; the catenary of a long line "
        "softens it further (low end)",
    ),
    "cog_z": dict(
        low=8.0,
        high=13.1,
        units="m",
        note="above the keel: a light deck cargo (8 m) to the highest CoG the IMO 2008 IS Code "
        "allows at the 5 m draft (GM_T >= 0.15 m; KM = 13.26 m). The 13.8 m the thesis's "
        "chapter 7 quotes gives GM_T = -0.54 m here: it capsizes",
    ),
    "radii_of_gyration": dict(
        low=(0.30, 0.22, 0.22),
        high=(0.40, 0.28, 0.28),
        units="B, L, L",
        note="the ends of Journee's ranges",
    ),
    "roll_damping": dict(
        low=0.02,
        high=0.10,
        units="of critical",
        note="bare barge (2 %) to bilge keels or skegs (10 %)",
    ),
}

#: ILLUSTRATIVE wind-load coefficients of Barge 2 with box-shaped deck cargo (OCIMF form,
#: eqs 2.25-2.27, on B·H, L·H, L²·H), against the relative wind angle it comes from (deg,
#: 0 = head wind, counter-clockwise; port-starboard symmetric). The curve shapes follow the
#: published OCIMF / Blendermann (1994) pattern for box-like superstructures (C_x ≈ −0.8 head
#: wind, +0.7 stern wind; C_y ≈ −0.9 beam wind; a small C_n turning the bow away from the
#: wind). The numbers are jaxtow's choice, NOT measured and NOT the thesis's table (its
#: Smit Barge 2 coefficients are unpublished). Replace them with model-test data.
BARGE2_WIND_TABLE = dict(
    angle_deg=[0, 15, 30, 45, 60, 75, 90, 105, 120, 135, 150, 165, 180],
    cx=[-0.80, -0.78, -0.70, -0.57, -0.40, -0.20, 0.00, 0.18, 0.35, 0.50, 0.61, 0.68, 0.70],
    cy=[0.0, -0.25, -0.48, -0.68, -0.82, -0.90, -0.92, -0.90, -0.82, -0.68, -0.48, -0.25, 0.0],
    cn=[0.0, -0.04, -0.07, -0.08, -0.07, -0.04, 0.0, 0.04, 0.07, 0.08, 0.07, 0.04, 0.0],
)

#: Thesis sea states (section 3.1, Table A.1): 1 = survival/stationary, 2 = sailing. Table
#: A.1's period T is taken as the JONSWAP peak period; the current is zero (a current is a
#: change of the relative speed).
SEA_STATES = {
    "survival": dict(hs=5.0, tp=10.5, wind_speed=20.0, current_speed=0.0),
    "sailing": dict(hs=2.4, tp=8.2, wind_speed=10.0, current_speed=0.0),
}

#: ILLUSTRATIVE ocean tug for the Barge 2 examples (quadratic pull curve): 40 t bollard
#: pull, pull vanishing at 7 m/s (13.6 kn), offshore towing efficiency 0.75 (the usual
#: industry factor). Not from the thesis (its tug is not specified).
ILLUSTRATIVE_TUG = dict(
    bollard_pull_t=40.0, free_speed=7.0, efficiency=0.75, resistance_coefficient=0.0
)

# Published values, thesis Table 3.7 (Hong et al. [37], Nam et al. [51]).
TABLE_3_7 = {
    "2a": dict(
        m=0.5943,
        Izz=0.0494,
        R0=0.0697,
        Xvv=-0.1999,
        Xrr=0.1288,
        Yv=-0.4003,
        Yr=0.0161,
        Yvvv=-1.2109,
        Yrrr=0.9199,
        Nv=-0.1692,
        Nr=-0.0639,
        Nvvv=0.1184,
    ),
    "2b": dict(
        m=0.5943,
        Izz=0.0494,
        R0=0.0747,
        Xvv=-0.3889,
        Xrr=-0.0924,
        Yv=-0.5998,
        Yr=0.0875,
        Yvvv=-0.3269,
        Yrrr=0.0,
        Nv=-0.0624,
        Nr=-0.1004,
        Nvvv=-0.4149,
    ),
}
