from typing import Any, Union

import os
import typing

def analyze(path: typing.Union[str,os.PathLike[str]], parameters: bool = ..., layout: str = ...) -> dict[str,typing.Any]: ...
