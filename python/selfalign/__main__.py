"""``python -m selfalign reproduce [--out DIR]`` (see selfalign.reproduce)."""

import sys

from .reproduce import main

if __name__ == "__main__":
    args = sys.argv[1:]
    if not args or args[0] != "reproduce":
        print("usage: python -m selfalign reproduce [--out DIR] [--quiet] [--only N ...] "
              "[--strict]", file=sys.stderr)
        sys.exit(2)
    sys.exit(main(args[1:]))
