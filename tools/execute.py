"""Execute notebooks in place, in this Python environment, with a finite time limit.

Used by ``make notebooks`` so that stored outputs are exactly what the code
computes (nbval then re-executes them under ``make test`` and compares)::

    python -m tools.execute notebooks/*.ipynb
"""
from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

__all__ = ["execute_notebook", "main"]


ADDRESS = re.compile(r"\b0x[0-9a-fA-F]{6,16}\b")   # the same token as notebooks/sanitize.cfg


def execute_notebook(path, timeout: int = 300, kernel_name: str = "python3") -> None:
    """Run every cell of ``path`` in a fresh kernel and save the outputs in place.

    Each cell has ``timeout`` seconds (never unlimited: a widget callback that
    waits forever must fail the build, not hang it). What would differ between
    two runs is left out: cell timings, widget state and view ids (random on
    every run), memory addresses. Two runs give byte-identical files.
    """
    import nbformat
    from nbclient import NotebookClient

    path = Path(path)
    nb = nbformat.read(path, as_version=4)
    NotebookClient(nb, timeout=timeout, startup_timeout=120, kernel_name=kernel_name,
                   record_timing=False, store_widget_state=False,
                   resources={"metadata": {"path": str(path.parent)}}).execute()
    nb.metadata.pop("widgets", None)        # state left by an earlier run is not removed by nbclient
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3 (dhlab)", "language": "python"}
    for cell in nb.cells:
        cell.metadata.pop("execution", None)
        if cell.cell_type == "code":
            cell.outputs = _coalesce_streams(cell.outputs)
        for out in cell.get("outputs", []):
            data = out.get("data", {})
            data.pop("application/vnd.jupyter.widget-view+json", None)
            if "text/plain" in data:
                data["text/plain"] = ADDRESS.sub("0xADDRESS", data["text/plain"])
    nbformat.write(nb, path)


def _coalesce_streams(outputs):
    """Join consecutive prints to the same stream: the kernel splits them into chunks
    at moments that vary between runs (nbval joins them too when it compares)."""
    merged = []
    for out in outputs:
        if (merged and out.get("output_type") == "stream" and merged[-1].get("output_type") == "stream"
                and merged[-1].get("name") == out.get("name")):
            merged[-1]["text"] += out["text"]
        else:
            merged.append(out)
    return merged


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("notebooks", nargs="+", type=Path)
    parser.add_argument("--timeout", type=int, default=300, help="seconds per cell (default 300)")
    args = parser.parse_args(argv)
    for path in args.notebooks:
        print(f"executing {path} ...", flush=True)
        execute_notebook(path, timeout=args.timeout)
    return 0


if __name__ == "__main__":
    sys.exit(main())
