"""Drive an implementation of DSPBR with the conformance vectors (docs/conformance.md).

    import dspbr.conformance as dc
    results = dc.run("conformance/vectors.json", my_eval)
    dc.write_results(results, "results.json")
    # then: dspbr conformance check conformance/vectors.json results.json --out report

my_eval(vector) receives one vector (a dict: "material" in the params instance form, "options",
"v", "l", ...; conventions of docs/bsdf.md) and returns its f(v, l) |l.z| as 3 numbers, or a dict
with "f_cos" and any of "pdf", "albedo", "emission", "delta". reference_eval is such a function:
the reference BSDF (tables="published" gives what a renderer using the published tables gets).
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


def _rgb(x, what, vid):
    try:
        vals = [float(c) for c in x]
    except (TypeError, ValueError):
        vals = None
    if vals is None or len(vals) != 3 or not all(math.isfinite(c) for c in vals):
        raise ValueError(f"vector {vid!r}: {what} must be 3 finite numbers, got {x!r}")
    return vals


def run(vectors, my_eval):
    """{"results": [...]} for `vectors` (a path, a loaded document or a list of vectors), one result
    per vector from my_eval(vector). Raises ValueError naming the vector when a value is not 3
    finite numbers (or, for pdf, one finite number)."""
    if isinstance(vectors, str):
        vectors = load(vectors)
    elif isinstance(vectors, dict):
        vectors = vectors["vectors"]
    results = []
    for v in vectors:
        out = my_eval(v)
        r = {"id": v["id"]}
        if isinstance(out, dict):
            r["f_cos"] = _rgb(out.get("f_cos"), "f_cos", v["id"])
            for key in _OPTIONAL:
                if key not in out or out[key] is None:
                    continue
                if key == "pdf":
                    p = float(out["pdf"])
                    if not math.isfinite(p):
                        raise ValueError(f"vector {v['id']!r}: pdf must be a finite number, got {out['pdf']!r}")
                    r["pdf"] = p
                elif key == "delta":
                    r["delta"] = [{"l": _rgb(d["l"], "delta l", v["id"]), "value": _rgb(d["value"], "delta value", v["id"])}
                                  for d in out["delta"]]
                else:
                    r[key] = _rgb(out[key], key, v["id"])
        else:
            r["f_cos"] = _rgb(out, "f_cos", v["id"])
        results.append(r)
    return {"results": results}


def write_results(results, path):
    """Writes the results of run() as JSON (the format `dspbr conformance check` reads), atomically:
    the text is made first (ValueError on a non-finite number, nothing written), then written to a
    temporary file next to `path` and renamed over it, so an old file stays whole on any failure."""
    from ._dspbr import write_text_atomically  # the compiled module
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
