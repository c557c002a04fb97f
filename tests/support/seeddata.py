"""The test data files: the verified seed cases (a copy of shared/reference/seed_cases.json)
and the A matrices printed in seed 002. Imported by the tests as ``seeddata``."""
import json
from pathlib import Path

DATA = Path(__file__).resolve().parents[2] / "dhlab" / "data"   # shipped with the package


def load_cases() -> list:
    return json.loads((DATA / "seed_cases.json").read_text(encoding="utf-8"))["cases"]
