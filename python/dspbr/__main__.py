"""`python3 -m dspbr --version`: the installed module's version (as `dspbr --version` prints it)
and where it was imported from."""
import argparse
import sys

import dspbr


def main(argv: "list[str] | None" = None) -> int:
    parser = argparse.ArgumentParser(prog="python3 -m dspbr",
                                     description="The DSPBR 2025x reference toolchain's Python module.")
    parser.add_argument("--version", action="store_true", help="print the version and the module's location")
    args = parser.parse_args(argv)
    if args.version:
        print(f"dspbr {dspbr.__version__} ({dspbr.__file__})")
        return 0
    parser.print_help()
    return 0


if __name__ == "__main__":
    sys.exit(main())
