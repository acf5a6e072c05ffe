"""Takes and corpora: read_take against `bunraku convert`, Corpus against `bunraku corpus`, the
zero-copy views, reprs and errors as exceptions with the command line's messages."""

from __future__ import annotations

import gc
import pathlib
import shutil

import numpy as np
import pytest

import bunraku
from conftest import SOURCE_DIR, cli_error, run_cli, same_bits, take_matrix

DATA = SOURCE_DIR / "tests" / "data" / "io"


def test_version_is_the_projects():
    assert bunraku.__version__
    cmake = (SOURCE_DIR / "CMakeLists.txt").read_text()
    assert f"VERSION {bunraku.__version__} " in cmake


@pytest.mark.parametrize("name,options", [
    ("semicolon_crlf.csv", {}),
    ("two_joint_chain.bvh", {}),
    ("two_joint_chain.bvh", {"all_joints": True}),
    ("fastrak_sample.txt", {"rate": 30.0}),
])
def test_read_take_matches_bunraku_convert(cli, tmp_path, name, options):
    """Every format the command line reads, through its reader and options: the values are the
    doubles `bunraku convert` writes, and Take.write writes the same file."""
    args = []
    if options.get("all_joints"):
        args.append("--all-joints")
    if "rate" in options:
        args += ["--rate", str(options["rate"])]
    converted = tmp_path / "cli.csv"
    result = run_cli(cli, "convert", DATA / name, "-o", converted, *args, check=False)
    if result.returncode != 0:
        # a file the command refuses must be refused by read_take with the same message
        with pytest.raises(bunraku.Error) as error:
            bunraku.read_take(str(DATA / name), **options)
        assert str(error.value) == cli_error(cli, "convert", DATA / name, "-o", converted, *args)
        return
    take = bunraku.read_take(str(DATA / name), **options)
    assert same_bits(take.values, take_matrix(converted))
    written = tmp_path / "python.csv"
    take.write(str(written))
    assert written.read_bytes() == converted.read_bytes()


def test_values_are_a_view_of_the_takes_memory(demo_corpus):
    take = demo_corpus.takes[0]
    a, b = take.values, take.values
    assert a.dtype == np.float64 and a.shape == (take.frames, len(take.channels))
    assert not a.flags.owndata
    assert a.__array_interface__["data"][0] == b.__array_interface__["data"][0]
    assert np.shares_memory(a, b)
    # the same buffer the corpus holds: a take fetched again points at the same memory
    assert demo_corpus.takes[0].values.__array_interface__["data"][0] == a.__array_interface__["data"][0]
    with pytest.raises(ValueError):
        a[0, 0] = 1.0  # read-only: the stage results are shared and immutable
    copy = np.array(a)
    assert copy.flags.owndata and np.array_equal(copy, a)


def test_a_view_keeps_its_take_alive(demo_dir):
    values = bunraku.Corpus.open(str(demo_dir)).takes[3].values
    expected = np.array(values)
    gc.collect()
    assert np.array_equal(values, expected)


def test_take_labels_channels_and_repr(demo_corpus):
    take = demo_corpus.cell(demo_corpus.functions[0], demo_corpus.emotions[1])[0]
    assert take.function == demo_corpus.functions[0]
    assert take.emotion == demo_corpus.emotions[1]
    assert take.take_index == 1
    assert take.labels["function"] == take.function
    assert len(take.channels) == 24 and take.channels[0] == "head.x"
    assert take.units[0] == "cm" and take.units[3] == "deg"
    assert take.rate_hz == demo_corpus.rate_hz
    text = repr(take)
    assert text.startswith("<bunraku.Take ") and take.name in text and f"{take.frames} frames x 24 channels" in text
    frame = take.to_pandas()
    assert list(frame.columns) == take.channels and frame.shape == take.values.shape


def test_skeleton_of_a_bvh_take():
    take = bunraku.read_take(str(DATA / "two_joint_chain.bvh"), all_joints=True)
    skeleton = take.skeleton
    assert skeleton is not None
    assert skeleton.frames == take.frames
    assert len(skeleton.joints) == len(skeleton.parents) and skeleton.parents[0] == -1
    rotations = skeleton.rotations
    assert rotations.shape == (take.frames, len(skeleton.joints), 4)
    assert not rotations.flags.owndata
    assert np.allclose(np.linalg.norm(rotations, axis=2), 1.0)
    assert skeleton.world_poses(0).shape == (len(skeleton.joints), 4, 4)
    assert "joints" in repr(skeleton)


def test_read_take_errors_are_the_command_lines(cli, tmp_path):
    missing = tmp_path / "missing.csv"
    with pytest.raises(bunraku.Error) as error:
        bunraku.read_take(str(missing))
    assert str(error.value).startswith(f"{missing}: ")  # `bunraku info` also reads folders: "no such file or folder"
    bad = tmp_path / "bad.csv"
    bad.write_text("time_s,head.x\n0,1\n0.2,oops\n")
    with pytest.raises(bunraku.Error) as error:
        bunraku.read_take(str(bad))
    assert str(error.value) == cli_error(cli, "info", bad)
    with pytest.raises(bunraku.Error) as error:
        bunraku.read_take(str(DATA / "semicolon_crlf.csv"), rate=-3.0)
    assert str(error.value) == cli_error(cli, "info", DATA / "semicolon_crlf.csv", "--rate", "-3")
    assert isinstance(error.value, ValueError)


def test_corpus_open_and_write_match_the_cli(cli, demo_dir, demo_corpus, tmp_path):
    assert len(demo_corpus) == 30 and len(demo_corpus.functions) == 2 and len(demo_corpus.emotions) == 3
    assert demo_corpus[-1].values.shape == demo_corpus.takes[-1].values.shape
    assert "30 takes" in repr(demo_corpus)
    ours = tmp_path / "ours"
    demo_corpus.write(str(ours))
    theirs = tmp_path / "theirs"
    run_cli(cli, "convert", demo_dir, "-o", theirs)
    for path in sorted(theirs.rglob("*")):
        if path.is_file():
            assert (ours / path.relative_to(theirs)).read_bytes() == path.read_bytes(), path.name
    reread = bunraku.Corpus.open(str(ours))
    for a, b in zip(reread.takes, demo_corpus.takes):
        assert same_bits(a.values, b.values)


def test_corpus_from_files_matches_bunraku_corpus(cli, demo_dir, tmp_path):
    files = tmp_path / "files"
    files.mkdir()
    for take in sorted((demo_dir).glob("*.csv"))[:6]:
        shutil.copy(take, files / take.name)
    pattern = "{function}_{emotion}_{take}"
    cli_folder = tmp_path / "cli-corpus"
    run_cli(cli, "corpus", files, "-o", cli_folder, "--pattern", pattern, "--name", "six")
    corpus = bunraku.Corpus.from_files([str(files)], pattern=pattern, name="six")
    ours = tmp_path / "ours"
    corpus.write(str(ours))
    for path in sorted(cli_folder.rglob("*")):
        if path.is_file():
            assert (ours / path.relative_to(cli_folder)).read_bytes() == path.read_bytes(), path.name
    with pytest.raises(bunraku.Error) as error:
        bunraku.Corpus.from_files([str(files)], pattern="{function}{emotion}")
    assert str(error.value) == cli_error(cli, "corpus", files, "-o", tmp_path / "x", "--pattern", "{function}{emotion}")


@pytest.mark.bandai
def test_bandai_waves_read_as_the_cli_reads_them(cli, bandai_waves, tmp_path):
    for path in bandai_waves[:3]:
        converted = tmp_path / (path.stem + ".csv")
        run_cli(cli, "convert", path, "-o", converted)
        take = bunraku.read_take(str(path))
        assert same_bits(take.values, take_matrix(converted)), path.name
        assert take.skeleton is not None and "Hips" in take.skeleton.joints
        assert take.skeleton.parts["hand"] == "Hand_R"


@pytest.mark.bandai
def test_bandai_corpus_from_files_matches_bunraku_corpus(cli, bandai_waves, tmp_path):
    cli_folder = tmp_path / "cli"
    pattern = "{function}_{emotion}_{take}"
    run_cli(cli, "corpus", *bandai_waves, "-o", cli_folder, "--pattern", pattern, "--name", "waves")
    corpus = bunraku.Corpus.from_files([str(p) for p in bandai_waves], pattern=pattern, name="waves")
    assert corpus.neutral_emotion == "normal" and len(corpus) == 15
    ours = tmp_path / "ours"
    corpus.write(str(ours))
    for path in sorted(cli_folder.rglob("*")):
        if path.is_file():
            assert (ours / path.relative_to(cli_folder)).read_bytes() == path.read_bytes(), path.name
