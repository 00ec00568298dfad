# A call the extension cannot convert says so in one line naming the function and the argument
# (python/dspbr/_guard.py), never in the binding library's words ("incompatible function
# arguments", "Invoked with", "Unable to cast", "vectorize"). The messages are checked word for
# word where they name a type, a count or a keyword; a guarded function still computes what the
# extension computes.
import math

import numpy as np
import pytest

import dspbr

BINDING_WORDS = ("incompatible", "Invoked with", "Unable to cast", "vectorize", "pybind11", "PYBIND11")

CASES = [
    (lambda: dspbr.Bsdf(sheen=3), TypeError, "dspbr.Bsdf(): sheen expects a string, got 3"),
    (lambda: dspbr.Bsdf({}, colour=1), TypeError,
     "dspbr.Bsdf(): unknown argument 'colour' (its arguments: material, components, sheen, tables, position, "
     "object_normal, wavelength, area, transmission_compensation)"),
    (lambda: dspbr.Bsdf({}, transmission_compensation="yes"), TypeError,
     "dspbr.Bsdf(): transmission_compensation expects True or False, got 'yes'"),
    (lambda: dspbr.Bsdf({}).eval([0, 0, 1]), TypeError, "dspbr.Bsdf.eval(): missing argument 'l'"),
    (lambda: dspbr.Bsdf({}).eval(v=[0, 0, 1], l=[0, 0, 1], x=1), TypeError,
     "dspbr.Bsdf.eval(): unknown argument 'x' (its arguments: v, l)"),
    (lambda: dspbr.lookup.ggx_E("x", 0.5), TypeError,
     "dspbr.lookup.ggx_E(): cos_theta expects a number or an array of numbers, got 'x'"),
    (lambda: dspbr.lookup.ggx_E([[1, 2], [3]], 0.5), TypeError,
     "dspbr.lookup.ggx_E(): cos_theta expects a number or an array of numbers, got [[1, 2], [3]]"),
    # numpy reads None as NaN and "0.5" as 0.5: the lookups took them (the sixth fresh tester's pass).
    (lambda: dspbr.lookup.ggx_E(None, 0.5), TypeError,
     "dspbr.lookup.ggx_E(): cos_theta expects a number or an array of numbers, got None"),
    (lambda: dspbr.lookup.ggx_E(0.5, roughness="0.5"), TypeError,
     "dspbr.lookup.ggx_E(): roughness expects a number or an array of numbers, got '0.5'"),
    (lambda: dspbr.lookup.glass_E([None, 1], 0.5, 1.5, 0), TypeError,
     "dspbr.lookup.glass_E(): cos_theta expects a number or an array of numbers, got [None, 1]"),
    (lambda: dspbr.lookup.ggx_E(1, 2, 3), TypeError, "dspbr.lookup.ggx_E() takes at most 2 arguments (3 given)"),
    (lambda: dspbr.lookup.ggx_E(cos_theta=0.5), TypeError, "dspbr.lookup.ggx_E(): missing argument 'roughness'"),
    (lambda: dspbr.lookup.ggx_E([0.1, 0.2], [0.1, 0.2, 0.3]), ValueError,
     "dspbr.lookup.ggx_E(): the arrays cannot be broadcast together (cos_theta (2,), roughness (3,))"),
    (lambda: dspbr.lut.axes("GGX_E", grid=3), TypeError, "dspbr.lut.axes(): grid expects a string, got 3"),
    (lambda: dspbr.scene.analyze("x.gltf", parameters="no"), TypeError,
     "dspbr.scene.analyze(): parameters expects True or False, got 'no'"),
]


@pytest.mark.parametrize("call, kind, message", CASES)
def test_refused_calls_name_the_argument(call, kind, message):
    with pytest.raises(kind) as e:
        call()
    assert str(e.value) == message
    assert not any(w in str(e.value) for w in BINDING_WORDS)


def test_guarded_functions_compute_as_before():
    # E_m at normal incidence tends to 1 as the roughness goes to 0 (a smooth mirror keeps all).
    assert math.isclose(float(dspbr.lookup.ggx_E(1.0, 0.0)), 1.0, abs_tol=1e-4)
    v = np.array([[0.0, 0.0, 1.0], [0.6, 0.0, 0.8]])
    b = dspbr.Bsdf({"roughness": 0.5})
    assert b.eval(v, v).shape == (2, 3)
    assert b.eval(v=v, l=v).tolist() == b.eval(v, v).tolist()
    assert dspbr.Bsdf.eval.__name__ == "eval" and "eval(self, v" in dspbr.Bsdf.eval.__doc__
