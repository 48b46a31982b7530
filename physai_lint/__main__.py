from physai_lint.cli import entry

entry()
