"""docs/validation.md lists every bundled case: its table is the case files' own, generated.

Regenerate the table after adding or changing a case: ``python -m tests.casebook.test_docs_table``
prints it; paste it between the two markers of docs/validation.md.
"""

from __future__ import annotations

from rockcli.casebook.load import load_casebook
from rockcli.casebook.schema import QUANTITIES
from tests.casebook.conftest import CASEBOOK, ROOT

DOC = ROOT / "docs" / "validation.md"
BEGIN = "<!-- casebook table: begin (generated, see tests/casebook/test_docs_table.py) -->"
END = "<!-- casebook table: end -->"


def cases_table() -> str:
    """The Markdown table of the bundled cases: id, quantity, expected, tolerance, source."""
    lines = [
        "| case | file | quantity | expected | tolerance | source |",
        "| --- | --- | --- | --- | --- | --- |",
    ]
    for loaded in load_casebook(CASEBOOK):
        case = loaded.case
        unit = QUANTITIES[case.kind][case.quantity]
        unit = "" if unit == "-" else f" [{unit}]"
        kind = "rel." if case.tolerance_type.value == "relative" else "abs."
        source = case.source.replace("|", "\\|")
        lines.append(
            f"| `{case.id}` | {loaded.file.rsplit('/', 1)[-1]} | {case.quantity}{unit} | "
            f"{case.expected:.7g} | {case.tolerance:g} {kind} | {source} |"
        )
    return "\n".join(lines)


def test_doc_table_is_the_case_files() -> None:
    text = DOC.read_text(encoding="utf-8")
    assert BEGIN in text and END in text
    table = text.split(BEGIN, 1)[1].split(END, 1)[0].strip()
    assert table == cases_table(), "run python -m tests.casebook.test_docs_table and paste it"


if __name__ == "__main__":
    print(BEGIN)
    print(cases_table())
    print(END)
