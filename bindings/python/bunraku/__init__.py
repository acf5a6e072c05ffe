"""Bunraku Motion Workbench for Python: the analysis layer as a NumPy module.

The stages of the thesis's chain are the C++ functions the workbench and the ``bunraku``
command call (analysis/pipeline), so they compute the same bits. Their keyword arguments are
named and defaulted as the keys of the JSON parameter file of ``bunraku analyse --parameters``
(docs/FORMATS.md) and are read by the same reader, so a bad value raises :class:`Error` with
the message the command line prints. Takes' ``values`` are read-only NumPy views of the takes'
own memory. Long calls release the GIL and stop on Ctrl-C (KeyboardInterrupt).

    >>> import bunraku
    >>> corpus = bunraku.Corpus.open("demo")
    >>> cell = bunraku.normalise(corpus, function="greeting", emotion="friendly")
    >>> [t.variance_normalised for t in cell.takes]

docs/PYTHON.md has a worked example.
"""

from __future__ import annotations

import json as _json
import os as _os
from typing import Any, Mapping, Optional, Sequence, Union

from . import _bunraku
from ._bunraku import (  # noqa: F401  (the public names)
    Analysis,
    Axes,
    CellAxis,
    Corpus,
    Decomposition,
    Designed,
    Error,
    Fluctuations,
    FunctionAxis,
    Gains,
    NormalisedCell,
    NormalisedTake,
    Normalisation,
    Parameters,
    Phase,
    Preprocessed,
    Skeleton,
    Take,
    TakeAxis,
    Kimono,
    read_take,
    relative_error,
)

__version__: str = _bunraku.__version__

__all__ = [
    "Analysis", "Axes", "CellAxis", "Corpus", "Decomposition", "Designed", "Error", "Fluctuations",
    "FunctionAxis", "Gains", "NormalisedCell", "NormalisedTake", "Normalisation", "Parameters", "Phase",
    "Preprocessed", "Skeleton", "Take", "TakeAxis", "Kimono", "__version__", "analyse", "decompose", "design",
    "emotion_weight", "fluctuations", "gains", "kimono", "motion_axis", "normalise", "parameters", "phase",
    "preprocess", "read_take", "relative_error",
]


def _plain(value: Any) -> Any:
    """NumPy scalars and arrays as the JSON numbers and lists they stand for."""
    if hasattr(value, "tolist"):
        return value.tolist()
    raise TypeError(f"{type(value).__name__} is not a parameter value")


def _parameters(where: str, sections: Mapping[str, Mapping[str, Any]]) -> Parameters:
    """The chain's parameters from JSON sections, read and validated as a parameters file is
    (analysis/pipeline/parameters_json.h); messages start with `where`."""
    return Parameters.from_json(_json.dumps(dict(sections), default=_plain), where)


def parameters(**sections: Mapping[str, Any]) -> Parameters:
    """Every parameter of the chain from sections named as in the parameters file:
    ``bunraku.parameters(normalise={"tau": 6}, decompose={"method": "least-squares"})``.
    Missing keys keep their defaults; errors are the file reader's."""
    return _parameters("bunraku.parameters()", sections)


# ---- thesis 2.2 -------------------------------------------------------------------------------

def preprocess(corpus: Corpus, *, pad: bool = True, unwrap: bool = True, alignStart: bool = True,
               alignHeading: bool = True, alignPosition: bool = True, positionAlignment: str = "rigid",
               referenceTake: int = 0, threads: int = 0) -> Preprocessed:
    """Thesis 2.2: pad takes to the longest (1), unwrap angles (Euler filter), align start times
    to each cell's reference take (3), start positions - one rigid translation per take, or
    ``positionAlignment="per-part"`` - and headings to each function's reference (4).
    ``referenceTake`` 0 picks each cell's time reference automatically (thesis 3.6.1).
    The pipeline's preprocess stage; keywords as the parameters file's "preprocess"."""
    p = _parameters("bunraku.preprocess()", {"preprocess": {
        "pad": pad, "unwrap": unwrap, "alignStart": alignStart, "alignHeading": alignHeading,
        "alignPosition": alignPosition, "positionAlignment": positionAlignment, "referenceTake": referenceTake}})
    return _bunraku._preprocess(corpus, p, threads)


def _preprocessed(source: Union[Corpus, Preprocessed], threads: int) -> Preprocessed:
    if isinstance(source, Preprocessed):
        return source
    if isinstance(source, Corpus):
        return preprocess(source, threads=threads)
    raise TypeError(f"expected a Corpus or a Preprocessed corpus, got {type(source).__name__}")


# ---- thesis 3 ---------------------------------------------------------------------------------

def normalise(corpus: Union[Corpus, Preprocessed], *, function: Optional[str] = None, emotion: Optional[str] = None,
              tau: int = 4, searchBand: int = 20, maxScale: int = 16, coupling: str = "auto",
              path: str = "optimal", reference: Union[str, int] = "suggested",
              cellReferences: Mapping[str, Union[str, int]] = {}, averageExcludesOutliers: bool = True,
              averageBase: int = 0, averageExcluded: Sequence[int] = (), scales: Sequence[float] = (),
              weighting: str = "none", level: str = "first-frame", approximationWeight: float = 0.0,
              threads: int = 0) -> Normalisation:
    """Thesis 3: wavelet matching of every cell's takes to its reference (3.5, cost eq. 3.28
    with the coupling of eq. 3.29), the variance evaluation (3.8, eq. 3.30) and the average
    take (3.7). With ``function`` and ``emotion``, that cell alone, as ``bunraku normalise``:
    the result's ``.takes[k].variance_raw`` / ``.variance_normalised`` are its ``--json``'s.

    A Corpus is preprocessed first with the defaults (thesis 2.2), as the command does; pass
    a :class:`Preprocessed` to choose. Keywords as the parameters file's "normalise": tau (half
    window, 3.5.2), searchBand (T_cmp, 3.5.1), maxScale (scales 1..maxScale), coupling
    ("auto": method2 on the puppet's 4 parts, chains on a skeleton's joints; independent, method1,
    method2, chains, per-part, per-coordinate, all, or sets), path ("optimal"
    or the thesis's "greedy" scan, 3.5.3), reference ("suggested" 3.6.1, "average" 3.7, or a
    take index), approximationWeight (M of eq. 5.17), ..."""
    p = _parameters("bunraku.normalise()", {"normalise": {
        "tau": tau, "searchBand": searchBand, "maxScale": maxScale, "coupling": coupling, "path": path,
        "reference": reference, "cellReferences": dict(cellReferences),
        "averageExcludesOutliers": averageExcludesOutliers, "averageBase": averageBase,
        "averageExcluded": list(averageExcluded), "scales": list(scales), "weighting": weighting,
        "level": level, "approximationWeight": approximationWeight}})
    return _bunraku._normalise(_preprocessed(corpus, threads), p, function, emotion, threads)


def _normalisation(source: Union[Corpus, Preprocessed, Normalisation], threads: int) -> Normalisation:
    if isinstance(source, Normalisation):
        return source
    if isinstance(source, Analysis):
        return source.normalisation
    return normalise(source, threads=threads)


# ---- thesis 4 ---------------------------------------------------------------------------------

def decompose(source: Union[Corpus, Preprocessed, Normalisation], *, input: str = "normalised", method: str = "km2o",
              M: int = 0, threads: int = 0) -> Decomposition:
    """Thesis 4: x^{ijk} = y^i + z^{ij} + eta^{ijk} (eq. 4.1). ``method="km2o"``: the
    KM2O-Langevin equation with exogenous inputs (4.4.4, eqs. 4.42/4.43), M (the correlation
    length) chosen by the relative error P over 1..M_max when 0; ``"least-squares"``: 4.3.1
    (eq. 4.8). ``input``: the normalised takes (4.1, default) or the "preprocessed" ones.
    A Corpus or Preprocessed corpus is normalised first with the defaults. Keywords as the
    parameters file's "decompose"."""
    p = _parameters("bunraku.decompose()", {"decompose": {"input": input, "method": method, "M": M}})
    return _bunraku._decompose(_normalisation(source, threads), p, threads)


def _decomposition(source: Any, threads: int) -> Decomposition:
    if isinstance(source, Decomposition):
        return source
    if isinstance(source, Analysis):
        return source.decomposition
    return decompose(source, threads=threads)


def fluctuations(source: Union[Corpus, Normalisation, Decomposition], *, armaP: int = 2, armaQ: int = 2,
                 welchSegment: int = 32, threads: int = 0) -> Fluctuations:
    """Thesis 4.3.2: Welch power spectra of the fluctuation eta (segments of ``welchSegment``
    samples) and ARMA(armaP, armaQ) models averaged per cell (Table 4.1, FPE eq. 4.10).
    Keywords as the parameters file's "fluctuations"."""
    p = _parameters("bunraku.fluctuations()", {"fluctuations": {"armaP": armaP, "armaQ": armaQ,
                                                                "welchSegment": welchSegment}})
    return _bunraku._fluctuations(_decomposition(source, threads), p, threads)


def emotion_weight(source: Union[Corpus, Normalisation, Decomposition], function: str, emotion: str, *,
                   emotionWeight: float = 1.0, threads: int = 0) -> Take:
    """Thesis 4.5, eq. 4.45: x = y^i + a z^{ij} with a = ``emotionWeight`` in [0, 3] - the
    workbench's weighted take and ``bunraku emotion``'s (the body's motion when the takes carry
    a skeleton; the per-channel x otherwise). Keyword as the parameters file's design.emotionWeight."""
    p = _parameters("bunraku.emotion_weight()", {"design": {"emotionWeight": emotionWeight}})
    return _bunraku._emotion_weight(_decomposition(source, threads), function, emotion, p)


# ---- thesis 5 ---------------------------------------------------------------------------------

def _axis_section(frontBack: str, massSpacing: float, masses: str, tau: int, searchBand: int, maxScale: int,
                  approximationWeight: float, level: str, path: str, controlSpacing: int,
                  refinementPasses: int, segments: str = "male") -> dict:
    return {"frontBack": frontBack, "massSpacing": massSpacing, "masses": masses, "segments": segments, "tau": tau,
            "searchBand": searchBand,
            "maxScale": maxScale, "approximationWeight": approximationWeight, "level": level, "path": path,
            "controlSpacing": controlSpacing, "refinementPasses": refinementPasses}


def motion_axis(source: Union[Take, Corpus, Preprocessed, Normalisation], *, frontBack: str = "shoulder",
                massSpacing: float = 1.0, masses: str = "model", segments: str = "male", tau: int = 4,
                searchBand: int = 30, maxScale: int = 16, approximationWeight: float = 8.0, level: str = "first-frame",
                path: str = "greedy", controlSpacing: int = 8, refinementPasses: int = 2,
                threads: int = 0) -> Union[TakeAxis, Axes]:
    """Thesis 5.2.1: the motion axis - principal axes of inertia of the posed body's mass points
    (``massSpacing`` cm apart, from the modelled puppet's solid or, with ``masses="primitives"``,
    the body description's primitives; axis x the shoulder's facing or the "principal" axis). A
    take of a skeleton's joints (``--all-joints``) integrates the performer's body segments instead,
    de Leva's (1996) ``segments="male"`` or ``"female"`` table (docs/MOTION-AXIS.md, "The whole body").

    Of a :class:`Take`: its :class:`TakeAxis` (what the 3D view draws). Of a corpus or a
    normalisation: the chain's motion-axes stage, an :class:`Axes` with every function's
    functional motion (the neutral cell's average take, 3.7) and every emotional cell's phase
    (5.3: wavelet matching with tau, searchBand, maxScale, approximationWeight M of eq. 5.17,
    path, control points every ``controlSpacing`` frames) and gains (5.4, ``refinementPasses``
    rounds). Keywords as the parameters file's "axis"."""
    p = _parameters("bunraku.motion_axis()", {"axis": _axis_section(
        frontBack, massSpacing, masses, tau, searchBand, maxScale, approximationWeight, level, path, controlSpacing,
        refinementPasses, segments)})
    if isinstance(source, Take):
        return _bunraku._take_axis(source, p)
    return _bunraku._axes(_normalisation(source, threads), p, threads)


def kimono(take: Take, *, massPerArea: float = 0.015, stretchCompliance: float = 0.0, bendCompliance: float = 2e-4,
           damping: float = 1.5, drag: float = 0.6, substepRate: float = 240.0, collisionMargin: float = 0.3,
           settleSeconds: float = 0.5) -> Kimono:
    """The kimono of ``take`` simulated as cloth (thesis 6, future work; docs/KIMONO.md): the skirt
    and the long sleeves driven by the take's parts, on the puppet the take is drawn with (fitted to
    its skeleton when it has one), as the workbench's Cloth box and ``bunraku convert --kimono``
    simulate it. Keywords: the cloth parameters (g/cm^2, cm/dyn, 1/s, Hz, cm, s), the names of a
    project's ``view.clothParameters``; a value outside its range raises :class:`Error` naming it."""
    if not isinstance(take, Take):
        raise TypeError(f"bunraku.kimono(): expected a Take, got {type(take).__name__}")
    cloth = {"massPerArea": massPerArea, "stretchCompliance": stretchCompliance, "bendCompliance": bendCompliance,
             "damping": damping, "drag": drag, "substepRate": substepRate, "collisionMargin": collisionMargin,
             "settleSeconds": settleSeconds}
    return _bunraku._kimono(take, cloth)


def _axes(source: Any, threads: int, axis: Mapping[str, Any]) -> Axes:
    if isinstance(source, Axes):
        if axis:
            raise TypeError("motion-axis keywords apply when the axes are computed, not to an Axes result")
        return source
    if isinstance(source, Analysis):
        return source.axes
    if isinstance(source, Take):
        raise TypeError("expected a corpus, a normalisation or an Axes result, got a Take")
    result = motion_axis(source, threads=threads, **axis)
    assert isinstance(result, Axes)
    return result


def phase(source: Union[Axes, Corpus, Normalisation], function: str, emotion: str, *, threads: int = 0,
          **axis: Any) -> Phase:
    """Thesis 5.3: the phase component of an emotional cell - its average take's motion axis
    matched to the functional one on all 6 axis DOF, the warp (emotional frame -> functional
    frame). From an :class:`Axes` result, or computed with motion_axis's keywords."""
    return _axes(source, threads, axis).cell(function, emotion).phase


def gains(source: Union[Axes, Corpus, Normalisation], function: str, emotion: str, *,
          boundaries: Optional[Sequence[int]] = None, threads: int = 0, **axis: Any) -> Gains:
    """Thesis 5.4: the amplitude component of an emotional cell - per phrase and axis DOF
    g0 (eq. 5.22) and g1 (eq. 5.23) of the functional axis against the phase-adjusted emotional
    axis. ``boundaries`` (functional frames, 0 ... last) re-extracts them for other phrases with
    the phase kept, as the workbench does when the user moves a boundary."""
    axes = _axes(source, threads, axis)
    if boundaries is None:
        return axes.cell(function, emotion).gains
    return _bunraku._gains(axes, function, emotion, [int(b) for b in boundaries])


def design(source: Union[Axes, Corpus, Normalisation], function: str, *, emotionWeight: float = 1.0,
           warp: Optional[Sequence[Sequence[float]]] = None, gains: Sequence[Mapping[str, Any]] = (),
           boundaries: Union[str, Sequence[int]] = "suggested", threads: int = 0, **axis: Any) -> Designed:
    """Thesis 5.5: the function's functional motion designed - gains on its axis per phrase
    (``gains``: [{"phrase", "dof", "g0", "g1"}]), recombined with the relative motion, time
    warped (``warp``: [[output frame, source frame], ...], None = the identity), over the
    phrase ``boundaries`` ("suggested" or inner frames). Keywords as the parameters file's
    "design" (emotionWeight is checked, and used by emotion_weight)."""
    p = _parameters("bunraku.design()", {"design": {
        "emotionWeight": emotionWeight, "warp": None if warp is None else [list(point) for point in warp],
        "gains": [dict(g) for g in gains], "boundaries": boundaries if isinstance(boundaries, str) else list(boundaries)}})
    return _bunraku._design(_axes(source, threads, axis), function, p)


# ---- the whole chain --------------------------------------------------------------------------

def analyse(corpus: Corpus, *, parameters: Union[None, Parameters, Mapping[str, Any], str, "_os.PathLike[str]"] = None,
            preprocess: Optional[Mapping[str, Any]] = None, normalise: Optional[Mapping[str, Any]] = None,
            decompose: Optional[Mapping[str, Any]] = None, fluctuations: Optional[Mapping[str, Any]] = None,
            axis: Optional[Mapping[str, Any]] = None, design: Optional[Mapping[str, Any]] = None,
            threads: int = 0) -> Analysis:
    """The thesis's whole chain, as ``bunraku analyse``: preprocess (2.2), normalise every cell
    (3), decompose (4), fluctuations (4.3.2), motion axes, phase and gains (5).

    ``parameters``: a :class:`Parameters`, a dict of sections, or a parameters JSON file (the
    file of ``--parameters``); the section keywords (dicts of the same keys) override it.
    ``threads`` 0 = one per hardware thread (the results are the same for any count)."""
    if parameters is None:
        base = Parameters()
    elif isinstance(parameters, Parameters):
        base = parameters
    elif isinstance(parameters, Mapping):
        base = _parameters("bunraku.analyse()", parameters)
    else:
        base = Parameters.read(_os.fspath(parameters))  # a parameters or project file, as --parameters reads it
    overrides = {name: section for name, section in (
        ("preprocess", preprocess), ("normalise", normalise), ("decompose", decompose),
        ("fluctuations", fluctuations), ("axis", axis), ("design", design)) if section is not None}
    if overrides:
        sections = _json.loads(base.to_json())
        for name, section in overrides.items():
            sections[name].update(section)
        base = _parameters("bunraku.analyse()", sections)
    return _bunraku._analyse(corpus, base, threads)
