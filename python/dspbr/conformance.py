"""Drive an implementation of DSPBR with the conformance vectors (docs/conformance.md).

    import dspbr.conformance as dc
    results = dc.run("conformance/vectors.json", my_eval)
    dc.write_results(results, "results.json")
    # then: dspbr conformance check conformance/vectors.json results.json --out report

my_eval(vector) receives one vector (a dict: "material" in the params instance form, "options",
"v", "l", ...; conventions of docs/bsdf.md) and returns its f(v, l) |l.z| as 3 numbers, or a dict
with "f_cos" and any of "pdf", "albedo", "emission", "delta". reference_eval is such a function:
the reference BSDF (tables="published" gives what a renderer using the published tables gets).
run_batched does the same for a vectorised implementation: one call per material, arrays in and out.
"""
import json
import math

FORMAT = "dspbr-conformance"
VERSION = 1
_OPTIONAL = ("pdf", "albedo", "emission", "delta")


def load(path):
    """The vectors of a vector file written by `dspbr conformance generate` (a list of dicts), read
    as `dspbr conformance check` reads it (docs/limits.md: a regular file of at most 16 MiB, strict
    JSON; ValueError naming the file otherwise)."""
    from ._dspbr import read_document  # the compiled module
    doc = read_document(path, "conformance vector file")
    if not isinstance(doc, dict) or doc.get("format") != FORMAT:
        raise ValueError(f"{path}: not a conformance vector file (\"format\" must be \"{FORMAT}\")")
    if doc.get("version") != VERSION:
        raise ValueError(f"{path}: version {doc.get('version')!r} is not supported (this module reads {VERSION})")
    return doc["vectors"]


def _number(x, what, vid):
    """x as a float when it is a real number (int, float or a numpy scalar of those kinds; not a
    bool, not a string); ValueError naming the vector otherwise."""
    import numbers
    if isinstance(x, bool) or not isinstance(x, numbers.Real) or isinstance(x, (str, bytes)):
        raise ValueError(f"vector {vid!r}: {what} must be a number, got {x!r}")
    try:
        value = float(x)
    except OverflowError:  # an int beyond a double's range
        raise ValueError(f"vector {vid!r}: {what} must be a finite number, got an integer of {int(x).bit_length()} bits") from None
    if not math.isfinite(value):
        raise ValueError(f"vector {vid!r}: {what} must be a finite number, got {x!r}")
    return value


def _rgb(x, what, vid):
    """3 finite numbers from a list, tuple or array of 3 (not a string)."""
    if isinstance(x, (str, bytes, dict)) or not hasattr(x, "__len__") or len(x) != 3:
        raise ValueError(f"vector {vid!r}: {what} must be 3 finite numbers, got {x!r}")
    return [_number(c, f"{what}[{k}]", vid) for k, c in enumerate(x)]


_KEYS = ("f_cos",) + _OPTIONAL


def run(vectors, my_eval):
    """{"results": [...]} for `vectors` (a path, a loaded document or a list of vectors), one result
    per vector from my_eval(vector). Raises ValueError naming the vector when what my_eval returns
    is not 3 finite numbers (or, for pdf, one finite number; booleans and strings are not numbers),
    or a dict with a key other than f_cos, pdf, albedo, emission and delta (a misspelt "pfd" would
    otherwise go unjudged)."""
    import difflib
    if isinstance(vectors, str):
        vectors = load(vectors)
    elif isinstance(vectors, dict):
        vectors = vectors["vectors"]
    results = []
    seen = set()
    for v in vectors:
        vid = v["id"]
        if vid in seen:  # the checker would refuse the results file
            raise ValueError(f"vector {vid!r} appears twice in the vectors")
        seen.add(vid)
        out = my_eval(v)
        r = {"id": vid}
        if isinstance(out, dict):
            for key in out:
                if key not in _KEYS:
                    near = difflib.get_close_matches(str(key), _KEYS, n=1)
                    hint = f" (did you mean {near[0]!r}?)" if near else ""
                    raise ValueError(f"vector {vid!r}: unknown key {key!r}{hint}; the keys are {', '.join(_KEYS)}")
            r["f_cos"] = _rgb(out.get("f_cos"), "f_cos", vid)
            for key in _OPTIONAL:
                if key not in out or out[key] is None:
                    continue
                if key == "pdf":
                    r["pdf"] = _number(out["pdf"], "pdf", vid)
                elif key == "delta":
                    if isinstance(out["delta"], (str, bytes, dict)) or not hasattr(out["delta"], "__iter__"):
                        raise ValueError(f"vector {vid!r}: delta must be a list of {{'l': ..., 'value': ...}}, "
                                         f"got {out['delta']!r}")
                    r["delta"] = []
                    for k, d in enumerate(out["delta"]):
                        if not isinstance(d, dict) or set(d) != {"l", "value"}:
                            raise ValueError(f"vector {vid!r}: delta[{k}] must be {{'l': [x, y, z], 'value': [r, g, b]}}, "
                                             f"got {d!r}")
                        r["delta"].append({"l": _rgb(d["l"], f"delta[{k}].l", vid),
                                           "value": _rgb(d["value"], f"delta[{k}].value", vid)})
                else:
                    r[key] = _rgb(out[key], key, vid)
        else:
            r["f_cos"] = _rgb(out, "f_cos", vid)
        results.append(r)
    return {"results": results}


def run_batched(vectors, my_eval_batch):
    """run() for a vectorised implementation: my_eval_batch(material, options, v, l) is called once per
    run of consecutive vectors that share a material and options (the set lists each material's
    vectors together), with v and l numpy arrays of shape (n, 3), and returns f(v, l) |l.z| as an
    array of shape (n, 3), or a dict with "f_cos" (n, 3) and optionally "pdf" (n,) (NaN: not
    supplied for that vector) or "albedo" / "emission" (n, 3). The results and their checks are
    run()'s: ValueError naming the vector for a value that is not finite, or a shape that does not
    match the batch."""
    import numpy as np
    if isinstance(vectors, str):
        vectors = load(vectors)
    elif isinstance(vectors, dict):
        vectors = vectors["vectors"]
    outputs = {}
    start = 0
    while start < len(vectors):
        key = json.dumps([vectors[start]["material"], vectors[start].get("options")], sort_keys=True)
        end = start + 1
        while end < len(vectors) and json.dumps([vectors[end]["material"], vectors[end].get("options")],
                                                sort_keys=True) == key:
            end += 1
        batch = vectors[start:end]
        v = np.array([x["v"] for x in batch], dtype=np.float64)
        l = np.array([x["l"] for x in batch], dtype=np.float64)
        out = my_eval_batch(batch[0]["material"], batch[0].get("options"), v, l)
        out = dict(out) if isinstance(out, dict) else {"f_cos": out}
        for name, value in out.items():
            if name == "delta":
                raise ValueError(f"vector {batch[0]['id']!r}: delta lobes are not batched (run() takes them per vector)")
            shape = (len(batch),) if name == "pdf" else (len(batch), 3)
            if name in _KEYS:
                value = np.asarray(value)
                if value.dtype.kind not in "iuf":  # numbers; not booleans, strings or objects
                    raise ValueError(f"vector {batch[0]['id']!r}: {name} of a batch must be an array of numbers, "
                                     f"got dtype {value.dtype}")
                value = value.astype(np.float64)
                if value.shape != shape:
                    raise ValueError(f"vector {batch[0]['id']!r}: {name} of a batch of {len(batch)} must have shape "
                                     f"{shape}, got {value.shape}")
            out[name] = value
        for k, x in enumerate(batch):
            r = {name: value[k] if name in _KEYS else value for name, value in out.items()}
            if "pdf" in r and math.isnan(r["pdf"]):
                r["pdf"] = None  # not supplied
            outputs[x["id"]] = r
        start = end
    return run(vectors, lambda x: outputs[x["id"]])


def write_results(results, path):
    """Writes the results of run() as JSON (the format `dspbr conformance check` reads), atomically:
    the text is made first (ValueError on a document that is not {"results": [{"id": ..., ...}]} or
    on a non-finite number, nothing written), then written to a
    temporary file next to `path` and renamed over it, so an old file stays whole on any failure."""
    import os
    from ._dspbr import write_text_atomically  # the compiled module
    folder = os.path.dirname(os.fspath(path)) or "."
    if not os.path.isdir(folder):  # as `conformance reference --out`: no folders made on the way
        raise ValueError(f"{path}: the folder '{folder}' does not exist (create it first)")
    if not isinstance(results, dict) or set(results) != {"results"} or not isinstance(results["results"], list):
        raise ValueError(f"{path}: results must be run()'s {{\"results\": [...]}}, got {type(results).__name__}"
                         + (f" with members {sorted(results)}" if isinstance(results, dict) else ""))
    for k, r in enumerate(results["results"]):
        if not isinstance(r, dict) or not isinstance(r.get("id"), str) or not set(r) <= {"id", *_KEYS}:
            raise ValueError(f"{path}: results[{k}] must be {{\"id\": str, \"f_cos\": ..., ...}} with keys among "
                             f"id, {', '.join(_KEYS)}; got {r!r:.200}")
    text = json.dumps(results, allow_nan=False) + "\n"
    write_text_atomically(path, text)


def reference_eval(vector, tables="renderer"):
    """The reference's f cos and pdf for a vector: dspbr.Bsdf with the vector's material and options."""
    from . import Bsdf  # the compiled module
    opts = vector.get("options") or {}
    kwargs = {"sheen": opts.get("sheen", "main"), "tables": tables}
    if "position" in opts:
        kwargs["position"] = tuple(opts["position"])
    if "object_normal" in opts:
        kwargs["object_normal"] = tuple(opts["object_normal"])
    b = Bsdf(vector["material"], **kwargs)
    v, l = vector["v"], vector["l"]
    f = b.eval(v, l)
    return {"f_cos": [float(c) * abs(l[2]) for c in f], "pdf": float(b.pdf(v, l))}
