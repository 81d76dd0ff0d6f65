"""The options of the strength computation as one typed value: :class:`StrengthOptions`.

Owns the options object accepted as ``options=`` by :func:`pressridge.strength` and
:func:`pressridge.xr.strength`, its validation, and the merging of it with the keyword
options of those functions (a keyword given explicitly overrides the object's field). The
names of the option values and of the parameters are the library's: the literals match the
Rust ``Participation``, ``Redistribution`` and ``StrengthFormula`` names, the parameters are
``ItdParams::FIELDS`` (read from the compiled module, not repeated here).
"""

from __future__ import annotations

import dataclasses
import os
import types
from typing import Any, Dict, Literal, Mapping, Optional, Tuple, get_args

from . import _core

#: Participation function: Lipscomb et al. (2007) (CICE ``krdg_partic = 1``, default) or
#: Thorndike et al. (1975) (0).
Participation = Literal["exponential", "thorndike"]
#: Ridged-ice redistribution: Lipscomb et al. (2007) (``krdg_redist = 1``, default) or
#: Hibler (1980) (0).
Redistribution = Literal["exponential", "uniform"]
#: Strength law: Rothrock (1975) with C_f (``kstrength = 1``, default) or Hibler (1979) (0).
StrengthLaw = Literal["rothrock", "hibler"]

_LITERALS: Dict[str, Tuple[str, ...]] = {
    "participation": get_args(Participation),
    "redistribution": get_args(Redistribution),
    "law": get_args(StrengthLaw),
}


@dataclasses.dataclass(frozen=True)
class StrengthOptions:
    """Options of :func:`pressridge.strength` and :func:`pressridge.xr.strength`, as one
    immutable value: ``pr.strength(aicen, vicen, options=StrengthOptions(law="hibler"))``.

    ``StrengthOptions()`` is CICE's default and gives, bit for bit, what the call without
    options gives. A keyword option given explicitly alongside ``options=`` overrides the
    same field (``strength(a, v, options=o, law="rothrock")``); parameter keywords
    (``mu_rdg=4.0``) are laid over :attr:`params`. Make variants with
    :func:`dataclasses.replace`.

    Attributes
    ----------
    participation : {"exponential", "thorndike"}
        Participation function: Lipscomb et al. (2007) (CICE ``krdg_partic = 1``, default)
        or Thorndike et al. (1975) (0).
    redistribution : {"exponential", "uniform"}
        Ridged-ice redistribution: Lipscomb et al. (2007) (``krdg_redist = 1``, default) or
        Hibler (1980) (0).
    law : {"rothrock", "hibler"}
        Rothrock (1975) energetics with C_f (``kstrength = 1``, default) or Hibler (1979)
        P = P* h exp(-C* (1 - A)) (0).
    cf : float, str, Table, path or (thickness, cf) pair, optional
        Frictional factor C_f (dimensionless; Rothrock only). Default None: CICE's 17
        (preset ``"cice"``). A number, a preset name (:data:`pressridge.CF_PRESETS`), a
        :class:`pressridge.Table`, a C_f table file, or ``(thickness_m, cf)`` nodes; see
        :func:`pressridge.strength`.
    friction : (float, float), optional
        With a table: the friction pair (mu, mu_w) (dimensionless) whose C_f to use.
        Default None: :data:`pressridge.DEFAULT_FRICTION` (1.0, 0.6).
    params : mapping of str to float
        Overrides of the ITD parameters by name, in their SI units (default: none, CICE's
        values). The parameters, their units and defaults:

    Raises
    ------
    ValueError
        An option value not among its literals, naming the field
        (``StrengthOptions.law = 'x': ...``); an unknown parameter name or a value that is
        not a number.
    """

    participation: Participation = "exponential"
    redistribution: Redistribution = "exponential"
    law: StrengthLaw = "rothrock"
    cf: Any = None
    friction: Optional[Tuple[float, float]] = None
    params: Mapping[str, float] = dataclasses.field(default_factory=dict)

    def __post_init__(self) -> None:
        for name, allowed in _LITERALS.items():
            value = getattr(self, name)
            if not isinstance(value, str) or value not in allowed:
                raise ValueError(
                    f"StrengthOptions.{name} = {value!r}: must be "
                    + " or ".join(f'"{a}"' for a in allowed)
                )
        if not isinstance(self.params, Mapping):
            raise ValueError(
                f"StrengthOptions.params must be a mapping of parameter names to numbers, "
                f"got {type(self.params).__name__}"
            )
        checked = {}
        for k, v in self.params.items():
            try:
                _core.check_param_name(k if isinstance(k, str) else repr(k), keyword=False)
            except ValueError as e:
                raise ValueError(f"StrengthOptions.params: {e}") from None
            if isinstance(v, bool) or not _is_number(v):
                raise ValueError(f"StrengthOptions.params: `{k}` must be a number, got {v!r}")
            checked[k] = float(v)
        # A read-only copy: the options object stays what it was made as.
        object.__setattr__(self, "params", types.MappingProxyType(checked))


def _is_number(v: Any) -> bool:
    try:
        float(v)
    except (TypeError, ValueError):
        return False
    return not isinstance(v, (str, bytes, os.PathLike))


# The parameters' list in the docstring, from the library (name, units, CICE default).
StrengthOptions.__doc__ = (StrengthOptions.__doc__ or "").replace(
    "values). The parameters, their units and defaults:\n",
    "values). The parameters, their units and defaults:\n\n"
    + "".join(
        f"        - ``{n}`` ({u}), default {d:g}: {desc}\n"
        for n, u, desc, d in _core.param_meta()
    ),
)

_DEFAULT = StrengthOptions()


def merge(
    options: Optional[StrengthOptions],
    participation: Optional[str],
    redistribution: Optional[str],
    law: Optional[str],
    cf: Any,
    friction: Any,
    params: Mapping[str, Any],
) -> Tuple[str, str, str, Any, Any, Dict[str, Any]]:
    """The options of a strength call: each keyword given (not None) wins over the field of
    ``options``, which wins over the default; parameters are ``options.params`` with
    ``params`` laid over them. Keyword values are checked by the library, as before."""
    if options is None:
        base = _DEFAULT
    elif isinstance(options, StrengthOptions):
        base = options
    else:
        raise TypeError(
            f"options must be a pressridge.StrengthOptions, got {type(options).__name__}"
        )
    return (
        base.participation if participation is None else participation,
        base.redistribution if redistribution is None else redistribution,
        base.law if law is None else law,
        base.cf if cf is None else cf,
        base.friction if friction is None else friction,
        {**base.params, **params},
    )
