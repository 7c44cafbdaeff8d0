"""The case layer from the shell (tools/case-lib.sh, tests/case/*.sh):

    python3 -m granair_cases render SRC DST KEY=VALUE ...   fill a template folder
    python3 -m granair_cases mesh DIR [NP]                  blockMesh (+ decomposePar)
    python3 -m granair_cases decompose DIR NP               decomposePar into NP subdomains
    python3 -m granair_cases run DIR NP APP [ARGS ...]      APP in DIR (mpirun for NP > 1)
    python3 -m granair_cases liggghts DIR NP [ARGS ...]     a stand-alone LIGGGHTS stage (build/bin/liggghts:
                                                            its errors reach the log; no -parallel)

Each step logs to DIR/log/<step>.log; a failure prints the log's tail and exits 1.
"""
import sys

from . import CaseError, runner, template


def main(argv):
    if len(argv) < 2 or argv[0] not in ("render", "mesh", "decompose", "run", "liggghts"):
        sys.exit(__doc__)
    cmd, args = argv[0], argv[1:]
    if cmd == "render":
        values = dict(kv.split("=", 1) for kv in args[2:])
        template.render(args[0], args[1], values)
    elif cmd == "mesh":
        runner.mesh(args[0], int(args[1]) if len(args) > 1 else 1)
    elif cmd == "decompose":
        runner.decompose(args[0], int(args[1]))
    elif cmd == "liggghts":
        runner.run(["liggghts"] + args[2:], args[0], "liggghts", np=int(args[1]), parallel=False)
    else:
        runner.run(args[2:], args[0], np=int(args[1]))


try:
    main(sys.argv[1:])
except CaseError as e:
    print(f"granair: {e}", file=sys.stderr)
    sys.exit(1)
