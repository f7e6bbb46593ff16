"""``python -m framefix mesh|analyze|correct|blocks|hexmesh PART [--size H] [--out DIR]`` and
``python -m framefix info``: the command line, in Python.

Same exit codes as the ``framefix`` program: 0 done, 2 bad input, 3 internal error.
"""
import argparse
import sys


STAGES = {"mesh": "mesh", "analyze": "singularities", "correct": "correct", "blocks": "blocks", "hexmesh": "hexmesh"}


def main(argv=None):
    argv = sys.argv[1:] if argv is None else list(argv)
    if argv[:1] == ["info"]:
        import framefix
        print(framefix._core.info_json())
        return 0
    parser = argparse.ArgumentParser(prog="python -m framefix")
    parser.add_argument("command", choices=sorted(STAGES))
    parser.add_argument("part")
    parser.add_argument("--size", type=float, default=0.0)
    parser.add_argument("--size-factor", type=float, default=1.0)
    parser.add_argument("--threads", type=int, default=0)
    parser.add_argument("--out", default="framefix-out")
    parser.add_argument("--method", default="auto")
    parser.add_argument("--budget-s", type=float, default=0.0)
    parser.add_argument("--fillet-rims", action="store_true")
    parser.add_argument("--hex-size", type=float, default=0.0)
    parser.add_argument("--layers", type=int, default=0)
    parser.add_argument("--order", type=int, default=1)
    parser.add_argument("--mesher", default="tetgen")
    parser.add_argument("--no-refine", action="store_true")
    parser.add_argument("--no-remesh-thin", action="store_true")
    try:
        args = parser.parse_args(argv)
    except SystemExit as e:
        return 2 if e.code else 0
    import framefix
    try:
        if args.command == "correct" and args.method == "none":
            raise framefix.Error("correct: method 'none' corrects nothing; use analyze, or --method snap")
        result = framefix.run(args.part, STAGES[args.command], args.method, args.size, args.size_factor,
                              args.threads, args.budget_s, args.fillet_rims, args.hex_size, args.layers, args.order,
                              mesher=args.mesher, refine=not args.no_refine,
                              remesh_thin=not args.no_remesh_thin)
        result.write_outputs(args.out)
    except framefix.Error as e:
        print(f"framefix: error [{str(e).split(':', 1)[0]}]: {str(e).split(': ', 1)[-1]}", file=sys.stderr)
        return 2
    except Exception as e:  # a backend bug: report it, never a stack trace
        print(f"framefix: internal error: {e}", file=sys.stderr)
        return 3
    print(result.human_summary)
    print(f"results: {args.out}/report.json")
    return 0


if __name__ == "__main__":
    sys.exit(main())
