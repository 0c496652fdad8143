"""TOML configs of the CLI subcommands: a built-in name (jaxtow/data) or a file path."""

from __future__ import annotations

import tomllib
from importlib import resources
from pathlib import Path


def config_text(config, builtin: dict) -> str:
    """The TOML text of ``config``: a key of ``builtin`` (name -> file in jaxtow/data) or a path."""
    if str(config) in builtin:
        return resources.files("jaxtow").joinpath("data", builtin[str(config)]).read_text()
    path = Path(config)
    if not path.is_file():
        raise ValueError(
            f"config {str(config)!r}: no such file (built-in configs: {sorted(builtin)})"
        )
    return path.read_text()


def read_config(config, builtin: dict) -> dict:
    """The parsed config (a dict passes through)."""
    if isinstance(config, dict):
        return config
    return tomllib.loads(config_text(config, builtin))


def config_dispatch(name: str, builtin: dict, run):
    """argparse ``func`` for a config subcommand: ``--show-config`` prints the config, else ``run(args)``."""

    def dispatch(args):
        if args.show_config:
            try:
                print(config_text(args.config, builtin))
            except ValueError as e:
                raise SystemExit(f"jaxtow {name}: {e}") from None
            return
        run(args)

    return dispatch
