"""Python's manners for the extension's functions: a call whose arguments the binding layer cannot
convert (a wrong type, a wrong count, an unknown keyword, arrays that do not broadcast) raises a
TypeError or ValueError whose one line names the function and the argument, instead of the binding
library's own text (its overload lists, "Invoked with", cast errors).

Each guarded function keeps its signature, read from the first docstring line the extension writes
("name(a: type = default, ...) -> result"); the checks run only once the extension has refused the
call, so a correct call costs nothing more. The one exception: an array argument (ArrayLike) of a
function (dspbr.lookup) that is neither an array nor a number is checked first, because numpy turns None into NaN and "0.5" into
0.5 where the extension asks for an array, and the call would go through.
"""
import functools
import os
import re
import types
from typing import Any, Callable, List, Optional, Tuple

import numpy

# The binding library's texts for a call it could not convert (never shown to the user).
_BINDING_TEXT = ("incompatible function arguments", "incompatible constructor arguments", "Unable to cast",
                 "vectorize")


def _split_top_level(text: str) -> List[str]:
    """Splits at commas outside brackets and quotes."""
    parts: List[str] = []
    depth, quote, start = 0, "", 0
    for i, ch in enumerate(text):
        if quote:
            quote = "" if ch == quote else quote
        elif ch in "'\"":
            quote = ch
        elif ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        elif ch == "," and depth == 0:
            parts.append(text[start:i].strip())
            start = i + 1
    if text[start:].strip():
        parts.append(text[start:].strip())
    return parts


def _parameters(doc: Optional[str]) -> Optional[List[Tuple[str, str, bool]]]:
    """[(name, annotation, has_default)] of the signature line, without self."""
    m = re.match(r"\s*\w*\((.*)\)\s*(->.*)?$", (doc or "").split("\n", 1)[0])
    if not m:
        return None
    out = []
    for p in _split_top_level(m.group(1)):
        if p in ("self", "*", "/") or p.startswith("self:"):
            continue
        name, _, rest = p.partition(":")
        annotation, _, default = rest.partition("=")
        out.append((name.strip(), annotation.strip(), bool(default.strip())))
    return out


def _kind(annotation: str) -> Optional[Tuple[str, Callable[[Any], bool]]]:
    """What an annotation accepts, in words, and a test for it (None: anything)."""
    a = annotation.replace("numpy.typing.", "").replace("typing.", "")
    optional = a.startswith("Optional[")
    if optional:
        a = a[len("Optional["):-1]
    tests: dict[str, Tuple[str, Callable[[Any], bool]]] = {
        "str": ("a string", lambda x: isinstance(x, str)),
        "float": ("a number", lambda x: isinstance(x, (int, float, numpy.floating, numpy.integer))
                  and not isinstance(x, bool)),
        "int": ("an integer", lambda x: isinstance(x, (int, numpy.integer)) and not isinstance(x, bool)),
        "bool": ("True or False", lambda x: isinstance(x, (bool, numpy.bool_))),
        "list[str]": ("a list of strings", lambda x: isinstance(x, (list, tuple)) and all(isinstance(s, str) for s in x)),
        "Union[str, os.PathLike[str]]": ("a file path", lambda x: isinstance(x, (str, os.PathLike))),
        "ArrayLike": ("a number or an array of numbers", _is_numeric_array),
    }
    if a not in tests:
        return None
    words, test = tests[a]
    if optional:
        return words + " or None", lambda x: x is None or test(x)
    return words, test


def _is_numeric_array(x: Any) -> bool:
    try:
        a = numpy.asarray(x)
    except (ValueError, TypeError):
        return False
    return a.dtype.kind in "biuf"


# Values that need no check before the call: arrays and numbers (anything else, a list of None or of
# strings included, is looked at by _explain).
_PLAIN = (numpy.ndarray, int, float, numpy.number, numpy.bool_)


def _short(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def _explain(qualname: str, params: List[Tuple[str, str, bool]], args: Tuple[Any, ...],
             kwargs: dict[str, Any]) -> Optional[Exception]:
    """The one-line reason the call does not fit the signature (None: it seems to)."""
    names = [p[0] for p in params]
    if len(args) > len(names):
        return TypeError(f"{qualname}() takes at most {len(names)} arguments ({len(args)} given)")
    given: dict[str, Any] = dict(zip(names, args))
    for k, v in kwargs.items():
        if k not in names:
            return TypeError(f"{qualname}(): unknown argument '{k}' (its arguments: {', '.join(names)})")
        if k in given:
            return TypeError(f"{qualname}(): argument '{k}' given twice")
        given[k] = v
    for name, _, has_default in params:
        if name not in given and not has_default:
            return TypeError(f"{qualname}(): missing argument '{name}'")
    arrays = []
    for name, annotation, _ in params:
        if name not in given:
            continue
        kind = _kind(annotation)
        if kind and not kind[1](given[name]):
            return TypeError(f"{qualname}(): {name} expects {kind[0]}, got {_short(given[name])}")
        if "ArrayLike" in annotation:
            arrays.append((name, numpy.shape(given[name])))
    try:
        numpy.broadcast_shapes(*[s for _, s in arrays])
    except ValueError:
        shapes = ", ".join(f"{n} {s}" for n, s in arrays)
        return ValueError(f"{qualname}(): the arrays cannot be broadcast together ({shapes})")
    return None


def guard(fn: Callable[..., Any], qualname: str, method: bool = False) -> Callable[..., Any]:
    """fn with the binding library's refusals turned into one-line messages (qualname: what the
    user called, e.g. "dspbr.lookup.ggx_E"). method: fn takes self first."""
    parsed = _parameters(fn.__doc__)
    if parsed is None:
        return fn
    params: List[Tuple[str, str, bool]] = parsed
    # (Methods check their arrays themselves: dspbr.Bsdf refuses strings and None with its own words.)
    has_arrays = not method and any("ArrayLike" in annotation for _, annotation, _ in params)

    @functools.wraps(fn)
    def call(*args: Any, **kwargs: Any) -> Any:
        user_args = args[1:] if method else args
        if has_arrays and not all(isinstance(v, _PLAIN) and not isinstance(v, (str, bytes))
                                  for v in (*user_args, *kwargs.values())):
            names = [p[0] for p in params]
            for name, value in (*zip(names, user_args), *kwargs.items()):
                annotation = next((a for n, a, _ in params if n == name), "")
                if "ArrayLike" in annotation and not _is_numeric_array(value):
                    raise TypeError(f"{qualname}(): {name} expects a number or an array of numbers, got {_short(value)}")
        try:
            return fn(*args, **kwargs)
        except (TypeError, ValueError, RuntimeError) as e:
            if not any(t in str(e) for t in _BINDING_TEXT):
                raise
            reason = _explain(qualname, params, user_args, kwargs)
            if reason is None:
                signature = (fn.__doc__ or "").split("\n", 1)[0].replace("self, ", "")
                reason = TypeError(f"{qualname}(): the arguments do not match {signature}")
            raise reason from None

    return call


def guarded_module(module: types.ModuleType, name: str) -> types.ModuleType:
    """A module like `module` (an extension submodule, left as it is: its stubs are made from it)
    whose functions are guarded; classes and constants are the same objects."""
    out = types.ModuleType(name, module.__doc__)
    for key in dir(module):
        value = getattr(module, key)
        if not key.startswith("_") and callable(value) and not isinstance(value, type):
            value = guard(value, f"{name}.{key}")
        setattr(out, key, value)
    return out


def guarded_class(cls: type, name: str) -> type:
    """A subclass of the extension class `cls` (left as it is) whose constructor and methods are
    guarded; its instances are instances of `cls`."""
    members: dict[str, Any] = {}
    for key, value in vars(cls).items():
        if (key == "__init__" or not key.startswith("_")) and callable(value) and not isinstance(value, type):
            members[key] = guard(value, name if key == "__init__" else f"{name}.{key}", method=True)
    members["__module__"] = name.rpartition(".")[0]
    members["__doc__"] = cls.__doc__
    return type(name.rpartition(".")[2], (cls,), members)
