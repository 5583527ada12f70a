"""Terminal views and plots of pin traces."""
from pathlib import Path

import pytest

from spinemu.analysis.view import parse_pins, render_changes, render_timeline, timeline_rows
from spinemu.trace import PinTrace, read_log

DATA = Path(__file__).parent.parent / "data" / "article"


def test_timeline_marks_high_low_floating_and_edges():
    t = PinTrace(1000, [(0, 0, 0), (10, 1, 0), (50, 1, 1)], end_cycle=100)
    assert timeline_rows(t, [0], 0, 100, 10)[0] == "·┃▁▁▁┃▔▔▔▔"


def test_timeline_of_the_demo_shows_enable_pin_high_after_start():
    t = read_log((DATA / "corrected_stepper_demo.trace").read_text())
    text = render_timeline(t, [0], 0, 80_000_000, 40, plain=True)
    row = text.splitlines()[0]
    assert row.split()[0] == "P0" and row.split()[1] == "┃" + "▔" * 39


def test_changes_table_lists_moving_pins():
    t = read_log((DATA / "corrected_stepper_demo.trace").read_text())
    lines = render_changes(t, limit=4, plain=True).splitlines()
    assert lines[1].split()[3:] == ["0000001e", "00000000", "P1↓", "P2↓", "P3↓", "P4↓"]
    assert lines[3].endswith("P0↑")


@pytest.mark.parametrize("spec,pins", [("0..4", [0, 1, 2, 3, 4]), ("4..1", [4, 3, 2, 1]), ("1,3", [1, 3])])
def test_pin_lists(spec, pins):
    assert parse_pins(spec) == pins


@pytest.mark.parametrize("spec", ["", "32", "a..b", "0..40"])
def test_bad_pin_lists_are_rejected(spec):
    with pytest.raises(ValueError):
        parse_pins(spec)


def test_plot_writes_a_png(tmp_path):
    pytest.importorskip("matplotlib")
    from spinemu.analysis.plot import plot_trace

    t = read_log((DATA / "corrected_stepper_demo.trace").read_text())
    out = tmp_path / "demo.png"
    fig = plot_trace(t, [0, 1, 2, 3, 4], 0, 40_000_000, path=str(out))
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert len(fig.axes[0].get_yticklabels()) == 5
