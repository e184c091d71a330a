"""``python -m selfalign reproduce [--out DIR]`` (see selfalign.reproduce),
``python -m selfalign regimes ...`` (the feeder's regime chart as CSV and PNG: selfalign.regimes)
and ``python -m selfalign identification-figure FIT_CSV PNG`` (the fit of ``selfalign identify
--fit-csv`` over the data, and its residuals: selfalign.identification_figures)."""

import sys

if __name__ == "__main__":
    args = sys.argv[1:]
    if args and args[0] == "reproduce":
        from .reproduce import main
        sys.exit(main(args[1:]))
    if args and args[0] == "regimes":
        from .regimes import main
        sys.exit(main(args[1:]))
    if args and args[0] == "identification-figure":
        from .identification_figures import main
        sys.exit(main(args[1:]))
    print("usage: python -m selfalign reproduce [--out DIR] [--quiet] [--only N ...] [--strict]\n"
          "       python -m selfalign regimes --mu-static S --mu-kinetic K [--csv FILE] "
          "[--png FILE] [...]\n"
          "       python -m selfalign identification-figure FIT_CSV PNG", file=sys.stderr)
    sys.exit(2)
