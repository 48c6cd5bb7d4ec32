"""Measured plants in MTG files: the multiscale graph, its tables and its tree."""
import os
import warnings

import pytest

import fspm

DATA = os.path.join(os.path.dirname(__file__), "..", "..", "tests", "data", "mtg")


def test_read_mtg_counts_the_entities_of_each_scale():
    # monopodial_plant.mtg: one plant, one axis, 5 growth units, 32 internodes (OpenAlea's
    # read_mtg gives the same counts).
    g = fspm.read_mtg(os.path.join(DATA, "openalea", "monopodial_plant.mtg"))
    assert g.scale_counts() == {1: 1, 2: 1, 3: 5, 4: 32}
    assert g.max_scale == 4
    assert ("diam", "REAL") in g.features


def test_to_dataframe_has_a_row_per_entity_and_a_column_per_feature():
    pandas = pytest.importorskip("pandas")
    g = fspm.read_mtg(os.path.join(DATA, "openalea", "monopodial_plant.mtg"))
    df = g.to_dataframe(4)
    assert isinstance(df, pandas.DataFrame)
    assert len(df) == 32
    assert list(df.columns[:7]) == ["vertex", "label", "symbol", "index", "complex", "parent",
                                    "edge"]
    # The first line of the file: /P1/A1/U1 with diam 4 on U1; E1 carries no diameter.
    units = g.to_dataframe(3)
    assert units["diam"].iloc[0] == 4.0
    assert set(df["symbol"]) == {"E"}


def test_units_scale_the_tree():
    path = os.path.join(DATA, "openalea", "test8_boutdenoylum2.mtg")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        in_metres = fspm.read_mtg(path).to_tree()
    # Centimetres read as metres: a tree hundreds of metres tall, and a warning naming the option.
    assert any("--length-unit" in str(w.message) for w in caught)
    in_cm = fspm.read_mtg(path, length_unit="cm", diameter_unit="mm").to_tree()
    z_m = in_metres.ends[:, 2].max() - in_metres.ends[:, 2].min()
    z_cm = in_cm.ends[:, 2].max() - in_cm.ends[:, 2].min()
    assert z_cm == pytest.approx(z_m / 100.0)
    assert in_metres.summary()["height"] > 100.0
    assert 1.0 < in_cm.summary()["height"] < 10.0


def test_a_missing_file_raises_file_not_found():
    with pytest.raises(FileNotFoundError):
        fspm.read_mtg(os.path.join(DATA, "no_such.mtg"))


def test_a_bad_unit_raises_value_error():
    with pytest.raises(ValueError):
        fspm.read_mtg(os.path.join(DATA, "openalea", "mtg1.mtg"), length_unit="inch")
