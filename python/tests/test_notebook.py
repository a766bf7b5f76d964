"""examples/notebooks/quickstart.ipynb runs top to bottom, and shows what it says it shows."""

import nbformat
from nbclient import NotebookClient

from conftest import ROOT

NOTEBOOK = ROOT / "examples" / "notebooks" / "quickstart.ipynb"


def outputs(cell):
    """The text of every output of a cell, by MIME type."""
    found = {}
    for output in cell.get("outputs", []):
        if output.get("output_type") == "stream":
            found["stream"] = found.get("stream", "") + output["text"]
        for mime, data in output.get("data", {}).items():
            found[mime] = found.get(mime, "") + (data if isinstance(data, str) else "".join(data))
    return found


def test_quickstart_runs_and_shows_its_results():
    nb = nbformat.read(NOTEBOOK, as_version=4)
    NotebookClient(nb, timeout=300, kernel_name="python3",
                   resources={"metadata": {"path": NOTEBOOK.parent}}).execute()
    code = [c for c in nb.cells if c.cell_type == "code"]
    page, d_y, sympy_cell, verdict, derivation, plot = (outputs(c) for c in code)
    # The page, as MathML, with its figure.
    assert "<math" in page["text/html"] and "<svg" in page["text/html"]
    assert "Sample Problem 18.4" in page["text/html"]
    # D_y: its number and unit, then its line as MathML.
    assert d_y["stream"].startswith("-129.75") and d_y["stream"].rstrip().endswith("N")
    assert "<math" in d_y["text/html"]
    # SymPy agrees with the hand form.
    assert sympy_cell["text/plain"] == "0"
    # The wrong claim: its named slip.
    assert verdict["stream"].strip() == "False cross-product-reversed"
    assert "cross-product-reversed" in verdict["text/html"]
    # The derivation: its lines judged, the last one following the slip.
    assert derivation["text/html"].count("<tr>") == 4 and ">follows<" in derivation["text/html"]
    # The simulation: within 1e-8 of the hand solution, and a plot.
    difference = float(plot["stream"].split(":")[1])
    assert difference < 1e-8
    assert "image/png" in plot
