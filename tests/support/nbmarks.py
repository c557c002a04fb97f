"""How a notebook cell tells nbval what to do with its outputs: a cell tag
(``nbval-check-output``, ``nbval-ignore-output``, ``raises-exception``, ``nbval-skip``),
which nbval reads as it reads its comment markers, and which, unlike a comment, does not
show on a slide."""


def tags(cell) -> set:
    return set(cell.get("metadata", {}).get("tags", []))


def checks_output(cell) -> bool:
    return cell.get("cell_type") == "code" and "nbval-check-output" in tags(cell)


def ignores_output(cell) -> bool:
    return cell.get("cell_type") == "code" and "nbval-ignore-output" in tags(cell)
