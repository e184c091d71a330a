"""``python -m selfalign reproduce [--out DIR]`` (see selfalign.reproduce) and
``python -m selfalign regimes ...`` (the feeder's regime chart as CSV and PNG: selfalign.regimes)."""

import sys

if __name__ == "__main__":
    args = sys.argv[1:]
    if args and args[0] == "reproduce":
        from .reproduce import main
        sys.exit(main(args[1:]))
    if args and args[0] == "regimes":
        from .regimes import main
        sys.exit(main(args[1:]))
    print("usage: python -m selfalign reproduce [--out DIR] [--quiet] [--only N ...] [--strict]\n"
          "       python -m selfalign regimes --mu-static S --mu-kinetic K [--csv FILE] "
          "[--png FILE] [...]", file=sys.stderr)
    sys.exit(2)
