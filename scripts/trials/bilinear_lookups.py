#!/usr/bin/env python3
"""Design trial (docs/design/renderer.md, "sixth run"; scripts/trials/lookup_trial.sh): a generated
C lookup header (dspbr lut --layout renderer: dspbr_lookup.h) with its two-axis bicubic reads made
bilinear, two taps per axis instead of four, at the same nodes (coordinate x in [0, 1] at x (N - 1))
and over the same tables. Not a mode of the library: the reads it rewrites are GGX_E, GGX_beta,
Sheen_E and Sheen_ash_E and the paired 1 - E_m / beta read of a dielectric base (with --ggx-only,
the sheen's stay bicubic).

With --no-exp, 1 - E_m,avg's exponential (the table holds its logarithm) becomes a multiply: a
timing of prepare without the libm call, whose values are wrong.

    bilinear_lookups.py IN.h OUT.h [--no-exp] [--keep-bicubic] [--ggx-only]
"""
import argparse
import re
import sys


def table_shape(text, name):
    """(rows, columns) of a generated table, from its accessor and its array."""
    cols = re.search(r"dspbr_%s_at\(int r, int c\) \{ return dspbr_%s_table\[r \* (\d+) \+ c\]" % (name, name), text)
    size = re.search(r"dspbr_%s_table\[(\d+)\]" % name, text)
    if not cols or not size:
        sys.exit(f"bilinear_lookups.py: no two-axis table {name} in the header")
    return int(size.group(1)) // int(cols.group(1)), int(cols.group(1))


def axis(tag, x, n, indent="  "):
    """The node index k<tag> and fraction f<tag> of coordinate x on n nodes."""
    return (f"{indent}float c{tag} = {x} * {n - 1}.0f;\n{indent}int k{tag} = (int)(c{tag});\n"
            f"{indent}if (k{tag} > {n - 2}) k{tag} = {n - 2};\n{indent}float f{tag} = c{tag} - (float)(k{tag});\n")


def bilinear(at, a, b):
    """The bilinear blend of accessor at's four nodes around (k<a>, k<b>)."""
    return (f"(({at}(k{a}, k{b}) * (1.0f - f{b}) + {at}(k{a}, k{b} + 1) * f{b}) * (1.0f - f{a}) + "
            f"({at}(k{a} + 1, k{b}) * (1.0f - f{b}) + {at}(k{a} + 1, k{b} + 1) * f{b}) * f{a})")


def replace_function(text, signature, body):
    start = text.find(signature)
    if start < 0:
        sys.exit(f"bilinear_lookups.py: no function '{signature}' in the header")
    end = text.index("\n}\n", start) + 3
    return text[:start] + signature + "\n" + body + "}\n" + text[end:]


def bilinear_reads(text, sheen):
    """The header with its GGX reads (and, if sheen, its sheen reads) bilinear."""
    clamp = "dspbr_lut_clampf({}, 0.0f, 1.0f)"
    for name in ["GGX_E", "GGX_beta"] + (["Sheen_E", "Sheen_ash_E"] if sheen else []):
        rows, cols = table_shape(text, name)
        text = replace_function(
            text, f"static inline float dspbr_lut_interp_dspbr_{name}(float x0, float x1) {{",
            axis("0", clamp.format("x0"), rows) + axis("1", clamp.format("x1"), cols) +
            f"  return {bilinear(f'dspbr_{name}_at', '0', '1')};\n")
    rows, cols = table_shape(text, "GGX_E")
    rows_b, cols_b = table_shape(text, "GGX_beta")
    if rows != rows_b:
        sys.exit("bilinear_lookups.py: GGX_E and GGX_beta have different roughness axes")
    text = replace_function(
        text, "static inline DspbrGgxMissingBeta dspbr_lut_ggx_missing_beta(float cos_theta, float roughness, int with_beta) {",
        "  float r = dspbr_lut_clampf(roughness, 0.0f, 1.0f);\n  float mu = dspbr_lut_clampf(cos_theta, 0.0f, 1.0f);\n"
        "  float xc = sqrtf(dspbr_lut_ggx_cos_t(mu, r * r));\n" + axis("r", "r", rows) + axis("c", "xc", cols) +
        "  DspbrGgxMissingBeta a;\n"
        f"  a.missing = dspbr_lut_clampf({bilinear('dspbr_GGX_E_missing_at', 'r', 'c')}, 0.0f, 1.0f);\n"
        "  a.beta = 0.0f;\n  if (with_beta != 0) {\n" + axis("b", "xc", cols_b, "    ") +
        "    float m = 1.0f - mu, m2 = m * m;\n"
        f"    a.beta = dspbr_lut_max0(m2 * m2 * m + {bilinear('dspbr_GGX_beta_at', 'r', 'b')});\n  }}\n  return a;\n")
    return text


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("header_in")
    parser.add_argument("header_out")
    parser.add_argument("--no-exp", action="store_true", help="1 - E_m,avg's exponential as a multiply (timing only)")
    parser.add_argument("--keep-bicubic", action="store_true", help="leave the reads bicubic (with --no-exp)")
    parser.add_argument("--ggx-only", action="store_true", help="leave the sheen's reads bicubic")
    args = parser.parse_args()
    text = open(args.header_in, encoding="utf-8").read()
    if not args.keep_bicubic:
        text = bilinear_reads(text, sheen=not args.ggx_only)
    if args.no_exp:
        call = "  return expf(dspbr_lut_interp_dspbr_GGX_E_avg("
        if call not in text:
            sys.exit("bilinear_lookups.py: no exponential of GGX_E_avg in the header")
        text = text.replace(call, "  return 0.1f * (dspbr_lut_interp_dspbr_GGX_E_avg(")
    open(args.header_out, "w", encoding="utf-8").write(text)


if __name__ == "__main__":
    main()
