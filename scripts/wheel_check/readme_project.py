"""Write the README's "Test your own shader" project into a folder, as a user pastes it
(scripts/check_wheel.sh runs it from the installed wheel on each Python the wheel claims).

    python scripts/wheel_check/readme_project.py DEST    # DEST/<the snippets' files>, DEST/run.sh

run.sh holds the README's runnable shell block(s), one command a line, for ``bash -e``; the
snippets are read by tests/docs/doc_snippets.py, the parser that tests/docs/ runs them with.
"""

import shlex
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "tests" / "docs"))
from doc_snippets import parse  # noqa: E402


def main(dest: Path) -> None:
    project = parse(REPO / "README.md")
    if not project.files or not project.shell:
        raise SystemExit("readme_project: README.md has no runnable project (<!-- runs: PATH --> and <!-- runs -->)")
    project.write(dest)
    (dest / "run.sh").write_text("".join(shlex.join(words) + "\n" for words in project.commands()), encoding="utf-8")


if __name__ == "__main__":
    main(Path(sys.argv[1]))
