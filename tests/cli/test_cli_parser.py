"""The command line's parser, built for one command or for all: the same options and help."""
import argparse

import pytest

from spinemu import cli


def _subparsers(parser):
    (action,) = [a for a in parser._actions if isinstance(a, argparse._SubParsersAction)]
    return action


def _all_help(parser) -> dict:
    """Every command's (and trace action's) help text."""
    out = {}
    for name, sub in _subparsers(parser).choices.items():
        out[name] = sub.format_help()
        nested = [a for a in sub._actions if isinstance(a, argparse._SubParsersAction)]
        for action in nested:
            for inner, p in action.choices.items():
                out[f"{name} {inner}"] = p.format_help()
    return out


@pytest.mark.parametrize("command", list(cli.COMMANDS))
def test_a_parser_built_for_one_command_parses_and_helps_as_the_full_one(command, monkeypatch):
    monkeypatch.setenv("COLUMNS", "100")
    full, one = cli.build_parser(), cli.build_parser(command)
    assert one.format_help() == full.format_help()
    full_help, one_help = _all_help(full), _all_help(one)
    for name, text in full_help.items():
        if name.split()[0] == command:
            assert one_help[name] == text


def test_the_help_lists_every_command_in_order():
    names = list(_subparsers(cli.build_parser()).choices)
    assert names == list(cli.COMMANDS) and names == list(_subparsers(cli.build_parser("run")).choices)


def test_run_options_parse_the_same_either_way():
    argv = ["run", "x.spin", "--cycles", "5", "--trace", "t.log", "--no-cache", "-q"]
    assert vars(cli.build_parser("run").parse_args(argv)) == vars(cli.build_parser().parse_args(argv))
