"""dspbr.conformance.load and write_results with hostile files (issue 45, findings 10 and 11): load
reads as `dspbr conformance check` does (docs/limits.md: regular files only, 16 MiB, strict JSON),
so a FIFO, /dev/zero, an oversized file, NaN / Infinity / 1e999 and duplicate keys are each a
one-line ValueError naming the file, never a hang or MemoryError; write_results replaces a file in
one rename, so a NaN in the results raises ValueError and leaves the old file byte for byte."""
import json
import os
import threading

import pytest

import dspbr.conformance as dc

GOOD = {"format": "dspbr-conformance", "version": 1, "vectors": [{"id": "a/00"}]}


def write(tmp_path, text, name="v.json"):
    p = tmp_path / name
    p.write_text(text)
    return p


def test_load_reads_a_good_file(tmp_path):
    assert dc.load(write(tmp_path, json.dumps(GOOD))) == [{"id": "a/00"}]


@pytest.mark.parametrize("bad, says", [
    ('{"format": "dspbr-conformance", "version": 1, "vectors": [], "x": NaN}', "malformed JSON"),
    ('{"format": "dspbr-conformance", "version": 1, "vectors": [], "x": Infinity}', "malformed JSON"),
    ('{"format": "dspbr-conformance", "version": 1, "vectors": [], "x": 1e999}', "overflows a double"),
    ('{"format": "dspbr-conformance", "version": 1, "version": 1, "vectors": []}', "duplicate key"),
])
def test_load_refuses_what_the_cli_refuses(tmp_path, bad, says):
    p = write(tmp_path, bad)
    with pytest.raises(ValueError) as e:
        dc.load(p)
    msg = str(e.value)
    assert str(p) in msg and says in msg and "\n" not in msg, msg


def test_load_refuses_a_file_over_the_limit(tmp_path):
    p = tmp_path / "big.json"
    with open(p, "w") as f:
        f.write('{"format": "dspbr-conformance", "version": 1, "vectors": [], "pad": "')
        f.write("x" * (16 << 20))
        f.write('"}')
    with pytest.raises(ValueError, match="larger than the limit"):
        dc.load(p)


def test_load_refuses_a_fifo_and_a_device(tmp_path):
    fifo = tmp_path / "fifo.json"
    os.mkfifo(fifo)
    # A writer that never writes: a reader that blocks on the FIFO would wait for ever; the
    # refusal comes from the opening, so no time limit is needed to see the difference.
    with pytest.raises(ValueError, match="not a regular file"):
        dc.load(fifo)
    with pytest.raises(ValueError, match="not a regular file"):
        dc.load("/dev/zero")


def test_write_results_is_atomic(tmp_path):
    p = tmp_path / "results.json"
    dc.write_results({"results": [{"id": "a/00", "f_cos": [0.1, 0.2, 0.3]}]}, p)
    old = p.read_bytes()
    assert json.loads(old)["results"][0]["id"] == "a/00"
    with pytest.raises(ValueError):
        dc.write_results({"results": [{"id": "a/00", "f_cos": [0.1, float("nan"), 0.3]}]}, p)
    assert p.read_bytes() == old
    assert sorted(os.listdir(tmp_path)) == ["results.json"]  # no temporary left
    dc.write_results({"results": [{"id": "b/00", "f_cos": [1, 2, 3]}]}, p)
    assert json.loads(p.read_text())["results"][0]["id"] == "b/00"
    assert sorted(os.listdir(tmp_path)) == ["results.json"]


# dspbr.conformance.run checks what the user's function returns (issue 45, poor list): a string,
# a boolean, a numeric string or an unknown key is a ValueError naming the vector (before: '123'
# became [1, 2, 3], True 1, '1e3' 1000, and a misspelt "pfd" was dropped unjudged).
@pytest.mark.parametrize("out, message", [
    ("123", "vector 'a': f_cos must be 3 finite numbers, got '123'"),
    ([True, 0, 0], "vector 'a': f_cos[0] must be a number, got True"),
    (["1e3", 0, 0], "vector 'a': f_cos[0] must be a number, got '1e3'"),
    ([float("nan"), 0, 0], "vector 'a': f_cos[0] must be a finite number, got nan"),
    ({"f_cos": [0, 0, 0], "pfd": 1}, "vector 'a': unknown key 'pfd' (did you mean 'pdf'?)"),
    ({"f_cos": [0, 0, 0], "pdf": "1"}, "vector 'a': pdf must be a number, got '1'"),
    ({"f_cos": [0, 0, 0], "delta": [{"l": [0, 0, 1]}]}, "vector 'a': delta[0] must be"),
])
def test_run_refuses_what_is_not_a_result(out, message):
    with pytest.raises(ValueError) as e:
        dc.run([{"id": "a"}], lambda v: out)
    assert str(e.value).startswith(message), str(e.value)


def test_run_takes_numbers_of_any_real_kind():
    np = pytest.importorskip("numpy")
    outs = [np.array([0.1, 0.2, 0.3]), (np.float32(1), 2, 3),
            {"f_cos": [0, 0, 0], "pdf": np.float64(2), "delta": [{"l": [0, 0, 1], "value": (1, 1, 1)}]}]
    results = [dc.run([{"id": "a"}], lambda v, o=o: o)["results"][0] for o in outs]
    assert results[0]["f_cos"] == [0.1, 0.2, 0.3]
    assert results[1]["f_cos"] == [1.0, 2.0, 3.0]
    assert results[2] == {"id": "a", "f_cos": [0.0, 0.0, 0.0], "pdf": 2.0,
                          "delta": [{"l": [0.0, 0.0, 1.0], "value": [1.0, 1.0, 1.0]}]}


# Found by the third fresh tester's pass: run() took duplicate ids (the checker then refuses the
# file) and an integer beyond a double's range raised OverflowError naming no vector;
# run_batched() took arrays of strings or booleans as numbers; write_results() wrote any document.
def test_run_refuses_duplicate_ids_and_huge_integers():
    with pytest.raises(ValueError, match="vector 'a' appears twice"):
        dc.run([{"id": "a"}, {"id": "a"}], lambda v: [0, 0, 0])
    with pytest.raises(ValueError, match=r"vector 'a': f_cos\[0\] must be a finite number, got an integer of 1101 bits"):
        dc.run([{"id": "a"}], lambda v: [2 ** 1100, 0, 0])


@pytest.mark.parametrize("value", [[["1", "2", "3"]], [[True, False, True]], [[None, 1, 2]]])
def test_run_batched_refuses_arrays_that_are_not_numbers(value):
    pytest.importorskip("numpy")
    vectors = [{"id": "a", "material": {"material": "generic"}, "v": [0, 0, 1], "l": [0, 0, 1]}]
    with pytest.raises(ValueError, match="vector 'a': f_cos of a batch must be an array of numbers, got dtype"):
        dc.run_batched(vectors, lambda m, o, v, l: value)


@pytest.mark.parametrize("doc", [[], {"results": {}}, {"results": [], "x": 1}, {"results": [{"f_cos": [0, 0, 0]}]},
                                 {"results": [{"id": "a", "pfd": 1}]}])
def test_write_results_refuses_what_run_does_not_make(tmp_path, doc):
    p = tmp_path / "results.json"
    with pytest.raises(ValueError, match="results"):
        dc.write_results(doc, p)
    assert os.listdir(tmp_path) == []


# Found by the fifth fresh tester's pass: write_results made every missing folder of a mistyped
# path (the CLI refuses it).
def test_write_results_makes_no_folders(tmp_path):
    p = tmp_path / "a" / "b" / "results.json"
    with pytest.raises(ValueError, match="the folder .* does not exist"):
        dc.write_results({"results": [{"id": "a", "f_cos": [0, 0, 0]}]}, p)
    assert os.listdir(tmp_path) == []
