"""examples/motostab.ipynb runs headless from top to bottom (nbclient), so that it cannot rot."""
import nbformat
from nbclient import NotebookClient

from conftest import SOURCE


def test_the_example_notebook_runs(tmp_path):
    notebook = nbformat.read(SOURCE / "examples" / "motostab.ipynb", as_version=4)
    assert not any(cell.get("outputs") for cell in notebook.cells if cell.cell_type == "code"), \
        "the notebook is kept without outputs"
    NotebookClient(notebook, timeout=120, kernel_name="python3", resources={"metadata": {"path": str(SOURCE)}}).execute()
    outputs = [o for cell in notebook.cells if cell.cell_type == "code" for o in cell.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    assert sum(1 for o in outputs if "image/png" in o.get("data", {})) >= 3  # the figures were drawn
