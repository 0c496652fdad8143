"""The jaxtow command line (in-process, small grids)."""

import json

import pytest

from jaxtow.cli import SUBCOMMANDS, main
from jaxtow.io import load_dataset


def test_help_lists_subcommands(capsys):
    with pytest.raises(SystemExit) as e:
        main(["--help"])
    assert e.value.code == 0
    out = capsys.readouterr().out
    for module in SUBCOMMANDS:
        assert module.__name__.rsplit(".", 1)[-1] in out


@pytest.mark.parametrize("module", SUBCOMMANDS, ids=lambda m: m.__name__.rsplit(".", 1)[-1])
def test_every_subcommand_has_help_with_an_output_option(module, capsys):
    """Each of the subcommands parses, prints its help and takes an output or tow option
    (the runs themselves are tested in the modules of their science: calm, equilibria, map,
    simulate here; drift, bifurcation, bem, resistance and report with theirs; study and tow
    in test_towfile)."""
    name = module.__name__.rsplit(".", 1)[-1]
    argv = {"report": [name, "waves", "--help"], "tow": [name, "show", "--help"]}.get(
        name, [name, "--help"]
    )
    with pytest.raises(SystemExit) as e:
        main(argv)
    assert e.value.code == 0
    out = capsys.readouterr().out
    assert f"usage: jaxtow {name}" in out and ("--out" in out or "tow" in out)


@pytest.mark.slow
def test_calm_writes_figures_datasets_summary(tmp_path, capsys):
    out = tmp_path / "res"
    main(
        [
            "calm",
            "--out",
            str(out),
            "--quiet",
            "--xp-grid",
            "0",
            "0.6",
            "13",
            "--l0-grid",
            "0.2",
            "2.5",
            "6",
            "--map-xp",
            "0",
            "0.6",
            "4",
            "--map-l0",
            "0.2",
            "2.5",
            "3",
            "--t1",
            "30",
            "--n-save",
            "301",
        ]
    )
    names = {p.name for p in out.iterdir()}
    for v in ("barge2a", "barge2b"):
        for stem in ("equilibria_vs_xp", "max_real_vs_l0", "map_xp_l0"):
            assert f"{v}_{stem}.png" in names and f"{v}_{stem}.nc" in names
    assert "barge2a_time_traces.png" in names and "barge2b_phase_portraits.png" in names
    summary = json.loads((out / "summary.json").read_text())
    assert summary["barge2b"]["time_domain"]["ended_early"] is False

    def stability(v):
        return [e["stability"] for e in summary[v]["design"]["equilibria"]]

    assert stability("barge2a") == ["unstable"]
    assert stability("barge2b") == ["unstable", "stable", "unstable"]
    ds = load_dataset(out / "barge2b_max_real_vs_l0.nc")
    assert ds.sizes["l0"] == 6
    assert "estimates" in capsys.readouterr().out


def test_equilibria_subcommand(capsys):
    main(["equilibria", "--tow", "barge2b", "--xp", "0.5", "--l0", "1.0", "--eigenvalues"])
    out = capsys.readouterr().out
    rows = [
        ln.split()
        for ln in out.splitlines()
        if ln.strip()[:1] in "-0123456789" and "eigenvalues" not in ln
    ]
    verdicts = [r[5] for r in rows]  # the verdict column of each equilibrium
    assert verdicts == ["unstable", "stable", "unstable"], out  # Barge 2b at x_p' = 0.5, l0' = 1
    assert out.count("eigenvalues:") == 3


def test_map_subcommand_and_overrides(tmp_path, capsys):
    main(
        [
            "map",
            "--tow",
            "barge2a",
            "--param",
            "l0",
            "0.2",
            "2.5",
            "5",
            "--param",
            "EA",
            "50",
            "400",
            "3",
            "--set",
            "a22=0.3",
            "--out",
            str(tmp_path),
            "--quiet",
            "--eigenvalues",
        ]
    )
    ds = load_dataset(tmp_path / "barge2a_l0_EA.nc")
    assert ds.attrs["vessel_a22"] == 0.3
    assert ds["eig_real"].dims[-1] == "mode" and ds.attrs["eigenvalue_method"] == "lapack"
    assert (tmp_path / "barge2a_l0_EA_map.png").exists()


def test_old_vessel_flag_and_spelling_still_work_with_a_deprecation_message(capsys):
    """One release of grace: --vessel barge_2b is --tow barge2b, with a message on stderr
    naming the new spelling; the numbers are the same."""
    main(["equilibria", "--vessel", "barge_2b", "--l0", "1.0"])
    old = capsys.readouterr()
    main(["equilibria", "--tow", "barge2b", "--l0", "1.0"])
    new = capsys.readouterr()
    assert old.out == new.out
    assert "--vessel is deprecated" in old.err and "'barge2b'" in old.err
    assert "deprecated" not in new.err


@pytest.mark.parametrize(
    "argv, text",
    [
        (["equilibria", "--l0", "-1"], "'l0'"),
        (["equilibria", "--set", "a22=-1"], "'a22'"),
        (["equilibria", "--set", "bogus=1"], "bogus"),
        (["map", "--param", "xp", "0", "3", "4", "--quiet"], "'xp'"),
        (["equilibria", "--vessel", "titanic"], "titanic"),
    ],
)
def test_bad_cli_input_is_a_clear_error(argv, text, tmp_path):
    if argv[0] == "map":
        argv = argv + ["--out", str(tmp_path)]
    with pytest.raises(SystemExit) as e:
        main(argv)
    assert text in str(e.value)


def test_simulate_subcommand(tmp_path, capsys):
    main(
        [
            "simulate",
            "--tows",
            "barge2b",
            "--t1",
            "40",
            "--n-save",
            "401",
            "--out",
            str(tmp_path),
        ]
    )
    for f in (
        "barge2b_time_traces.png",
        "barge2b_phase_portraits.png",
        "barge2b_forces.png",
        "simulate_summary.json",
    ):
        assert (tmp_path / f).exists()
    assert "barge2b" in capsys.readouterr().out
