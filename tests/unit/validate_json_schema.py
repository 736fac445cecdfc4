"""Validates JSON files against a JSON Schema (draft 2020-12), one line each.

Usage: validate_json_schema.py SCHEMA FILE...
Prints "valid FILE" or "invalid FILE: the first error"; exit status 3 when
the jsonschema module is missing (the caller skips).
"""
import json
import sys

try:
    import jsonschema
except ImportError:
    print("python3-jsonschema is not installed")
    sys.exit(3)

with open(sys.argv[1], encoding="utf-8") as f:
    schema = json.load(f)
jsonschema.Draft202012Validator.check_schema(schema)
validator = jsonschema.Draft202012Validator(schema)
for path in sys.argv[2:]:
    with open(path, encoding="utf-8") as f:
        error = jsonschema.exceptions.best_match(validator.iter_errors(json.load(f)))
    print(("valid " + path) if error is None else f"invalid {path}: {error.message}")
