from typing import Any, Union

import os
import typing

def analyze(path: typing.Union[str,os.PathLike[str]], parameters: bool = ...) -> dict[str,typing.Any]: ...
