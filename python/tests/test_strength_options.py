"""pressridge.StrengthOptions: the options of strength as one typed value, accepted as
``options=`` by pressridge.strength and pressridge.xr.strength; equal to the keyword form."""

from __future__ import annotations

import dataclasses
import typing

import numpy as np
import pytest
import xarray as xr

import pressridge as pr
import pressridge.xr as prx


@pytest.fixture(scope="module")
def itd(sample):
    with xr.open_dataset(sample) as ds:
        return ds.load()


def np_strength(itd, **kw):
    return pr.strength(itd.aicen.values, itd.vicen.values, itd.aice0.values, **kw)


def test_default_equals_the_call_without_options(itd):
    want = np_strength(itd)
    np.testing.assert_array_equal(np_strength(itd, options=pr.StrengthOptions()), want)
    np.testing.assert_array_equal(
        prx.strength(itd, options=pr.StrengthOptions()).values, prx.strength(itd).values
    )


NON_DEFAULT = [
    (dict(participation="thorndike", redistribution="uniform"), {}),
    (dict(law="hibler"), {}),
    (dict(cf="flato1991"), {}),
    (dict(cf=2.0), {}),
    (dict(params={"mu_rdg": 4.0, "gstar": 0.2}), dict(mu_rdg=4.0, gstar=0.2)),
]


@pytest.mark.parametrize("fields,params", NON_DEFAULT, ids=lambda x: str(x))
def test_options_equal_the_keyword_form(itd, fields, params):
    opts = pr.StrengthOptions(**fields)
    kw = {k: v for k, v in fields.items() if k != "params"}
    want = np_strength(itd, **kw, **params)
    assert not np.array_equal(want, np_strength(itd), equal_nan=True)
    np.testing.assert_array_equal(np_strength(itd, options=opts), want)
    np.testing.assert_array_equal(
        prx.strength(itd, options=opts).values, prx.strength(itd, **kw, **params).values
    )


def test_keywords_override_the_options(itd):
    opts = pr.StrengthOptions(law="hibler", params={"mu_rdg": 4.0, "pstar": 3e4})
    # An explicit keyword wins over the field; parameter keywords are laid over params.
    np.testing.assert_array_equal(
        np_strength(itd, options=opts, law="rothrock", pstar=2e4),
        np_strength(itd, law="rothrock", mu_rdg=4.0, pstar=2e4),
    )
    attrs = prx.strength(itd, options=opts, pstar=2e4).attrs
    assert attrs["strength_formula"] == "hibler"
    assert attrs["parameter_overrides"] == "mu_rdg=4.0, pstar=20000.0"


@pytest.mark.parametrize(
    "field,value", [("participation", "linear"), ("redistribution", "x"), ("law", "Rothrock")]
)
def test_bad_literal_names_the_field(field, value):
    with pytest.raises(ValueError, match=rf"StrengthOptions\.{field} = '{value}'"):
        pr.StrengthOptions(**{field: value})


def test_bad_params_and_options_type(itd):
    with pytest.raises(ValueError, match="unknown parameter `mu_rgd`"):
        pr.StrengthOptions(params={"mu_rgd": 4.0})
    with pytest.raises(ValueError, match="`pstar` must be a number"):
        pr.StrengthOptions(params={"pstar": "big"})
    with pytest.raises(TypeError, match="options must be a pressridge.StrengthOptions"):
        np_strength(itd, options={"law": "hibler"})


def test_typed_frozen_and_listed():
    hints = typing.get_type_hints(pr.StrengthOptions)
    assert typing.get_args(hints["participation"]) == ("exponential", "thorndike")
    assert typing.get_args(hints["redistribution"]) == ("exponential", "uniform")
    assert typing.get_args(hints["law"]) == ("rothrock", "hibler")
    o = pr.StrengthOptions(params={"mu_rdg": 4})
    with pytest.raises(dataclasses.FrozenInstanceError):
        o.law = "hibler"  # type: ignore[misc]
    with pytest.raises(TypeError):
        o.params["mu_rdg"] = 5.0  # type: ignore[index]
    assert dataclasses.replace(o, law="hibler").params == {"mu_rdg": 4.0}
    assert "StrengthOptions" in pr.__all__
    # The docstring lists every parameter with its units and default, from the library.
    for name in pr.PARAMETERS:
        assert f"``{name}``" in (pr.StrengthOptions.__doc__ or "")
