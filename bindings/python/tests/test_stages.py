"""The stages against the command line's output files, bit for bit, on the demo corpus: the
whole chain against `bunraku analyse`, each stage's arrays against its data files, one cell
against `bunraku normalise --json`, the weighted take against `bunraku emotion`; parameters
validated with the parameters file's messages."""

from __future__ import annotations

import inspect
import json

import numpy as np
import pytest

import bunraku
from conftest import cli_error, load_json, read_csv_rows, run_cli, same_bits, take_matrix


def stem(*labels) -> str:
    return "_".join(str(label) for label in labels)


def test_analyse_writes_the_bytes_bunraku_analyse_writes(demo_analysis, demo_cli_analysis, tmp_path):
    files = demo_analysis.data_files()
    assert "summary.json" in files and "parameters.json" in files
    on_disk = {p.name for p in demo_cli_analysis.iterdir() if p.is_file() and p.name != "report.html"}
    on_disk.discard(".bunraku-manifest")
    assert set(files) <= on_disk | {".bunraku-manifest"}
    for name, content in files.items():
        assert (demo_cli_analysis / name).read_bytes() == content, name
    demo_analysis.write(str(tmp_path / "out"))
    for name in files:
        assert (tmp_path / "out" / name).read_bytes() == (demo_cli_analysis / name).read_bytes()
    summary = load_json(demo_cli_analysis / "summary.json")
    assert demo_analysis.keys == summary["keys"]
    assert "cells" in repr(demo_analysis)


def test_preprocess_matches_the_preprocessed_files(demo_corpus, demo_cli_analysis):
    result = bunraku.preprocess(demo_corpus)
    assert result.key == load_json(demo_cli_analysis / "summary.json")["keys"]["preprocess"]
    for take in result.corpus.takes:
        path = demo_cli_analysis / f"preprocessed_{stem(take.function, take.emotion, take.take_index)}.csv"
        assert same_bits(take.values, take_matrix(path)), path.name
    report = result.to_pandas()
    assert len(report) == len(demo_corpus)


def test_normalise_matches_the_normalised_and_variance_files(demo_analysis, demo_cli_analysis):
    normalisation = bunraku.normalise(demo_analysis.preprocessed)
    assert normalisation.key == demo_analysis.keys["normalise"]
    assert len(normalisation.cells) == 6
    for cell in normalisation.cells:
        s = stem(cell.function, cell.emotion)
        assert same_bits(cell.reference_take.values, take_matrix(demo_cli_analysis / f"reference_{s}.csv"))
        assert same_bits(cell.average.values, take_matrix(demo_cli_analysis / f"average_{s}.csv"))
        for t in cell.takes:
            k = stem(s, t.take)
            assert same_bits(t.normalised.values, take_matrix(demo_cli_analysis / f"normalised_{k}.csv")), k
            rows = read_csv_rows(demo_cli_analysis / f"correspondence_{k}.csv")[1:]
            correspondence = np.array([[int(x) for x in row[1:]] for row in rows])  # one column per coupling set
            channels = {tuple(column) for column in t.correspondence.T}
            assert t.correspondence.shape == (cell.reference_take.frames, 24)
            assert all(tuple(column) in channels for column in correspondence.T), k
        rows = read_csv_rows(demo_cli_analysis / f"variance_{s}.csv")
        raw = np.array([[float(x) for x in row[3:]] for row in rows[1:] if row[1] == "raw"])
        normalised = np.array([[float(x) for x in row[3:]] for row in rows[1:] if row[1] == "normalised"])
        assert same_bits(cell.variance_raw, raw) and same_bits(cell.variance_normalised, normalised)
        totals = [float(row[2]) for row in rows[1:] if row[1] == "normalised"]
        assert [t.variance_normalised for t in cell.takes] == totals
        frame = cell.to_pandas()
        assert list(frame.columns[:3]) == ["take", "stage", "total"] and len(frame) == 2 * len(cell.takes)
    summary = load_json(demo_cli_analysis / "summary.json")
    for cell, entry in zip(normalisation.cells, summary["cells"]):
        assert (cell.function, cell.emotion, cell.reference) == (entry["function"], entry["emotion"], entry["reference"])
        assert cell.variance_normalised_total == entry["variance_normalised_total"]


def test_one_cell_matches_bunraku_normalise_json(cli, demo_dir, demo_corpus, tmp_path):
    function, emotion = demo_corpus.functions[1], demo_corpus.emotions[2]
    out = tmp_path / "cell"
    summary = json.loads(run_cli(cli, "normalise", demo_dir, "--function", function, "--emotion", emotion,
                                 "-o", out, "--json").stdout)
    result = bunraku.normalise(demo_corpus, function=function, emotion=emotion)
    assert len(result.cells) == 1
    assert [t.to_dict() for t in result.takes] == summary["takes"]
    assert [t.variance_raw for t in result.takes] == [t["variance_raw"] for t in summary["takes"]]
    assert [t.variance_normalised for t in result.takes] == [t["variance_normalised"] for t in summary["takes"]]
    assert result.reference == summary["reference"]
    assert result.suggested_reference == summary["suggested_reference"]
    assert result.variance_raw_total == summary["variance_raw_total"]
    for t in result.takes:
        path = out / f"{function}_{emotion}_{t.take}_normalised.csv"
        assert same_bits(t.normalised.values, take_matrix(path))
    assert "NormalisedTake" in repr(result.takes[0])
    with pytest.raises(bunraku.Error) as error:
        bunraku.normalise(demo_corpus, function=function, emotion="nope")
    assert str(error.value).startswith(f"no takes for {function}/nope in ")
    with pytest.raises(bunraku.Error):
        bunraku.normalise(demo_corpus).takes


def test_decompose_matches_the_component_files(demo_analysis, demo_cli_analysis):
    decomposition = bunraku.decompose(demo_analysis.normalisation)
    assert decomposition.method == "km2o" and decomposition.input == "normalised"
    summary = load_json(demo_cli_analysis / "summary.json")["decomposition"]
    assert decomposition.M == summary["M"]
    assert decomposition.candidate_M == summary["candidate_M"]
    assert decomposition.mean_P_percent_by_M == summary["mean_P_percent_by_M"]
    assert decomposition.mean_P_percent == summary["mean_P_percent"]
    for function in decomposition.functions:
        assert same_bits(decomposition.function_take(function).values, take_matrix(demo_cli_analysis / f"y_{function}.csv"))
        assert not decomposition.y(function).flags.owndata
    for function, emotion in decomposition.cells:
        assert same_bits(decomposition.z(function, emotion), take_matrix(demo_cli_analysis / f"z_{function}_{emotion}.csv"))
    rows = read_csv_rows(demo_cli_analysis / "km2o_errors.csv")
    errors = np.array([[float(x) for x in row[1:]] for row in rows[1:]])
    assert same_bits(decomposition.cell_error_percent, errors)
    frame = decomposition.to_pandas()
    assert list(frame.index) == [row[0] for row in rows[1:]] and list(frame.columns) == rows[0][1:]
    assert "M = " in repr(decomposition)


def test_fluctuations_match_the_arma_table_and_spectra(demo_analysis, demo_cli_analysis):
    fluctuations = bunraku.fluctuations(demo_analysis.decomposition)
    rows = read_csv_rows(demo_cli_analysis / "arma_table.csv")
    frame = fluctuations.to_pandas()
    assert list(frame.columns) == rows[0]
    assert len(frame) == len(rows) - 1
    for (_, ours), theirs in zip(frame.iterrows(), rows[1:]):
        assert [ours["channel"], ours["function"], ours["emotion"], str(ours["takes"])] == theirs[:4]
        assert same_bits(np.array(ours.values[4:], dtype=float), np.array([float(x) for x in theirs[4:]]))
    spectra = read_csv_rows(demo_cli_analysis / "spectra.csv")[1:]
    function, emotion = fluctuations.cells[0]
    channel = fluctuations.channels[0]
    theirs = [(float(r[3]), float(r[4])) for r in spectra if r[:3] == [function, emotion, channel]]
    assert same_bits(fluctuations.frequency_hz(function, emotion), np.array([f for f, _ in theirs]))
    assert same_bits(fluctuations.power(function, emotion)[:, 0], np.array([p for _, p in theirs]))


def test_emotion_weight_matches_bunraku_emotion(cli, demo_dir, demo_analysis, tmp_path):
    function, emotion = demo_analysis.corpus.functions[0], demo_analysis.corpus.emotions[1]
    out = tmp_path / "weighted.csv"
    run_cli(cli, "emotion", demo_dir, "--function", function, "--emotion", emotion, "--weight", "0.5",
            "--per-channel", "-o", out)
    take = bunraku.emotion_weight(demo_analysis.decomposition, function, emotion, emotionWeight=0.5)
    assert same_bits(take.values, take_matrix(out))
    with pytest.raises(bunraku.Error) as error:
        bunraku.emotion_weight(demo_analysis.decomposition, function, emotion, emotionWeight=7)
    assert "parameters.design.emotionWeight: expected a number in [0, 3], got the number 7" in str(error.value)


def test_axes_phase_gains_match_the_axis_files(demo_analysis, demo_cli_analysis):
    axes = bunraku.motion_axis(demo_analysis.normalisation)
    assert isinstance(axes, bunraku.Axes)
    for f in axes.functions:
        assert same_bits(f.coordinates, take_matrix(demo_cli_analysis / f"axis_functional_{f.function}.csv"))
    summary = {(a["function"], a["emotion"]): a for a in load_json(demo_cli_analysis / "summary.json")["axes"]}
    for cell in axes.cells:
        s = stem(cell.function, cell.emotion)
        assert same_bits(cell.coordinates, take_matrix(demo_cli_analysis / f"axis_emotional_{s}.csv"))
        phase = bunraku.phase(axes, cell.function, cell.emotion)
        warp = np.array([[float(x) for x in row] for row in read_csv_rows(demo_cli_analysis / f"warp_{s}.csv")[1:]])
        assert same_bits(phase.control_points, warp)
        e2f = np.array([float(row[1]) for row in read_csv_rows(demo_cli_analysis / f"phase_{s}.csv")[1:]])
        assert same_bits(phase.emotional_to_functional, e2f)
        assert phase.cost == summary[(cell.function, cell.emotion)]["phase_cost"]
        gains = bunraku.gains(axes, cell.function, cell.emotion)
        rows = read_csv_rows(demo_cli_analysis / f"gains_{s}.csv")
        frame = gains.to_pandas()
        assert list(frame.columns) == rows[0]
        assert same_bits(frame["g0"].to_numpy(), np.array([float(r[4]) for r in rows[1:]]))
        assert same_bits(frame["g1"].to_numpy(), np.array([float(r[5]) for r in rows[1:]]))
        assert gains.g0.shape == (len(gains.phrases), 6)
        assert cell.design_relative_error == summary[(cell.function, cell.emotion)]["design_relative_error"]
        approximation = np.array([[float(x) for x in r[1:7]] for r in read_csv_rows(demo_cli_analysis / f"approximation_{s}.csv")[1:]])
        assert same_bits(cell.approximation_error, approximation)
    # other phrase boundaries: the phase kept, gains re-extracted
    cell = axes.cells[0]
    frames = axes.function(cell.function).coordinates.shape[0]
    regained = bunraku.gains(axes, cell.function, cell.emotion, boundaries=[0, frames // 2, frames - 1])
    assert len(regained.phrases) == 2


def test_design_with_no_edits_is_the_functional_motion(demo_analysis):
    axes = demo_analysis.axes
    function = axes.functions[0]
    designed = bunraku.design(axes, function.function)
    assert designed.take.frames == function.take.frames
    assert np.allclose(designed.axis_coordinates, function.coordinates, atol=1e-9)
    frames = function.take.frames
    slower = bunraku.design(axes, function.function, warp=[[0, 0], [2 * (frames - 1), frames - 1]],
                            gains=[{"phrase": 0, "dof": 2, "g0": 1.0, "g1": 1.5}])
    assert slower.take.frames == 2 * (frames - 1) + 1
    assert bunraku.relative_error(slower.axis_coordinates, slower.axis_coordinates) == 0.0


def test_motion_axis_of_a_take_matches_bunraku_axis(cli, demo_dir, tmp_path):
    path = demo_dir / "greeting_friendly_2.csv"
    take = bunraku.read_take(str(path))
    axis = bunraku.motion_axis(take)
    assert isinstance(axis, bunraku.TakeAxis)
    run_cli(cli, "axis", path, "-o", tmp_path / "axis.csv")
    assert same_bits(axis.take.values, take_matrix(tmp_path / "axis.csv"))
    run_cli(cli, "axis", path, "--coordinates", "-o", tmp_path / "coordinates.csv")
    assert same_bits(axis.coordinates, take_matrix(tmp_path / "coordinates.csv"))
    assert axis.poses.shape == (take.frames, 4, 4)


def test_keywords_are_the_parameter_files_keys_and_defaults():
    defaults = json.loads(bunraku.Parameters().to_json())
    stages = {
        bunraku.preprocess: ("preprocess", {"referenceTake": "referenceTake"}),
        bunraku.normalise: ("normalise", {}),
        bunraku.decompose: ("decompose", {}),
        bunraku.fluctuations: ("fluctuations", {}),
        bunraku.motion_axis: ("axis", {}),
    }
    for function, (section, _) in stages.items():
        signature = inspect.signature(function)
        for key, value in defaults[section].items():
            assert key in signature.parameters, f"{function.__name__} lacks {key}"
            default = signature.parameters[key].default
            if isinstance(default, (tuple, dict)):
                default = list(default) if isinstance(default, tuple) else dict(default)
            assert default == value, f"{function.__name__}({key}={default!r}) but the file's default is {value!r}"
    design = inspect.signature(bunraku.design).parameters
    for key, value in defaults["design"].items():
        default = design[key].default
        assert (list(default) if isinstance(default, tuple) else default) == value


@pytest.mark.parametrize("section,keyword,value", [
    ("normalise", "tau", 500),
    ("normalise", "path", "fastest"),
    ("normalise", "maxScale", 2.5),
    ("decompose", "method", "pca"),
    ("fluctuations", "armaP", 9),
    ("axis", "massSpacing", 0.1),
])
def test_bad_parameters_raise_the_parameter_files_message(cli, demo_dir, demo_corpus, tmp_path, section, keyword, value):
    file = tmp_path / "parameters.json"
    file.write_text(json.dumps({section: {keyword: value}}))
    expected = cli_error(cli, "analyse", demo_dir, "-o", tmp_path / "out", "--parameters", file)
    assert expected.startswith(f"{file}: parameters.{section}.{keyword}: ")
    stage = {"normalise": bunraku.normalise, "decompose": bunraku.decompose, "fluctuations": bunraku.fluctuations,
             "axis": bunraku.motion_axis}[section]
    with pytest.raises(bunraku.Error) as error:
        stage(demo_corpus, **{keyword: value})
    assert str(error.value) == expected.replace(f"{file}: ", f"bunraku.{stage.__name__}(): ", 1)
    with pytest.raises(bunraku.Error) as error:
        bunraku.analyse(demo_corpus, parameters=str(file))
    assert str(error.value) == expected


def test_run_time_errors_are_the_chains_messages(cli, demo_dir, demo_corpus, tmp_path):
    """A value in its range that fails at run time (M beyond M_max): the stage's error, named
    by the stage, as `bunraku analyse` prints it after naming the corpus and the file."""
    file = tmp_path / "parameters.json"
    file.write_text(json.dumps({"decompose": {"M": 999}}))
    expected = cli_error(cli, "analyse", demo_dir, "-o", tmp_path / "out", "--parameters", file)
    with pytest.raises(bunraku.Error) as error:
        bunraku.decompose(demo_corpus, M=999)
    message = str(error.value)
    assert message.startswith("Decomposition (4): ")
    assert expected == f"{demo_dir} with the parameters of {file}: {message}"
    with pytest.raises(bunraku.Error) as error:
        bunraku.analyse(demo_corpus, parameters=str(file))
    assert str(error.value) == message


@pytest.mark.bandai
def test_analyse_of_the_bandai_waves_writes_the_bytes_bunraku_analyse_writes(cli, bandai_waves, tmp_path):
    folder = tmp_path / "waves"
    run_cli(cli, "corpus", *bandai_waves, "-o", folder, "--name", "waves")
    out = tmp_path / "analysis"
    run_cli(cli, "analyse", folder, "-o", out)
    analysis = bunraku.analyse(bunraku.Corpus.open(str(folder)))
    files = analysis.data_files()
    assert len(files) > 50
    for name, content in files.items():
        assert (out / name).read_bytes() == content, name
    # the stages one by one give the chain's results
    normalisation = bunraku.normalise(bunraku.Corpus.open(str(folder)))
    cell = normalisation.cell("wave-right-hand", "exhausted")
    assert same_bits(cell.average.values, take_matrix(out / "average_wave-right-hand_exhausted.csv"))
    decomposition = bunraku.decompose(normalisation)
    assert same_bits(decomposition.z("wave-right-hand", "active"), take_matrix(out / "z_wave-right-hand_active.csv"))
    axes = bunraku.motion_axis(normalisation)
    phase = bunraku.phase(axes, "wave-right-hand", "active")
    e2f = np.array([float(row[1]) for row in read_csv_rows(out / "phase_wave-right-hand_active.csv")[1:]])
    assert same_bits(phase.emotional_to_functional, e2f)


def test_the_remaining_accessors_agree_with_the_cli_files(demo_analysis, demo_cli_analysis, tmp_path):
    summary = load_json(demo_cli_analysis / "summary.json")
    # the parameters: the chain's, as parameters.json holds them; the builder and the file reader agree
    assert json.loads(demo_analysis.parameters.to_json()) == load_json(demo_cli_analysis / "parameters.json")["parameters"]
    file = tmp_path / "p.json"
    file.write_text(json.dumps({"parameters": {"normalise": {"tau": 6}, "decompose": {"method": "least-squares"}}}))
    assert bunraku.parameters(normalise={"tau": 6}, decompose={"method": "least-squares"}) == bunraku.Parameters.read(str(file))
    # the normalised corpus is the cells' normalised takes
    normalisation = demo_analysis.normalisation
    for take in normalisation.corpus.takes:
        k = stem(take.function, take.emotion, take.take_index)
        assert same_bits(take.values, take_matrix(demo_cli_analysis / f"normalised_{k}.csv")), k
    first = normalisation.cells[0].takes[0]
    assert first.body_time.shape == (normalisation.cells[0].reference_take.frames,)
    assert first.families and {"family", "unit", "raw", "normalised"} == set(first.families[0])
    # decomposition: the cell means are the normalised takes' frame-wise means (positions; eq. 4.22)
    decomposition = demo_analysis.decomposition
    f, e = decomposition.cells[1]
    takes = [t.values for t in normalisation.corpus.cell(f, e)]
    assert np.allclose(decomposition.cell_mean(f, e)[:, :3], np.mean(takes, axis=0)[:, :3], atol=1e-9)
    assert decomposition.y(f).shape == decomposition.z(f, e).shape
    # axes: boundaries and errors as summary.json reports them
    axes = demo_analysis.axes
    for entry in summary["axes"]:
        cell = axes.cell(entry["function"], entry["emotion"])
        assert cell.undesigned_relative_error == entry["undesigned_relative_error"]
        assert axes.function(entry["function"]).boundaries == entry["phrase_boundaries"]
    function = axes.functions[0]
    designed = bunraku.design(axes, function.function, boundaries=[function.take.frames // 2])
    assert designed.take.frames == function.take.frames
    with pytest.raises(bunraku.Error) as error:
        bunraku.design(axes, function.function, boundaries=[5, 3])
    assert "parameters.design.boundaries[1]: expected increasing whole frames" in str(error.value)


def test_kimono_of_a_take_matches_bunraku_convert_kimono(cli, demo_dir, tmp_path):
    path = demo_dir / "greeting_friendly_2.csv"
    take = bunraku.read_take(str(path))
    kimono = bunraku.kimono(take)
    assert isinstance(kimono, bunraku.Kimono)
    run_cli(cli, "convert", path, "--kimono", "-o", tmp_path / "kimono.csv")
    converted = take_matrix(tmp_path / "kimono.csv")
    assert converted.shape == (take.frames, 24 + 18)
    assert same_bits(kimono.points, converted[:, 24:])
    assert same_bits(kimono.take.values, converted[:, 24:])
    assert kimono.take.channels[0] == "sleeve_right_tip.x"
    # The particles of a frame, visited out of order, are the simulation's: the measured points
    # are particles of the cloth.
    last = kimono.particles(kimono.frames - 1)
    first = kimono.particles(0)
    assert last.shape == first.shape and last.shape[1] == 3
    for point in range(6):
        row = kimono.points[kimono.frames - 1, 3 * point:3 * point + 3]
        assert np.any(np.all(last == row, axis=1))
    assert kimono.triangles.shape[1] == 3 and int(kimono.triangles.max()) < last.shape[0]
    measures = kimono.measures()
    assert set(measures) == {"sleeve_swing_right_cm", "sleeve_swing_left_cm", "sleeve_lag_s", "hem_swing_cm", "hand_swing_cm"}
    # Other cloth, other motion; a value out of range raises the range's message.
    softer = bunraku.kimono(take, damping=0.2, bendCompliance=0.01)
    assert not same_bits(softer.points, kimono.points)
    with pytest.raises(bunraku.Error, match="cloth.damping"):
        bunraku.kimono(take, damping=-1.0)
