"""Maps the top-level data folders rules/ and schemas/ into the installed package."""
from setuptools import find_packages, setup

setup(
    packages=find_packages(include=["physai_lint", "physai_lint.*"])
    + ["physai_lint._rules", "physai_lint._schemas"],
    package_dir={"physai_lint._rules": "rules", "physai_lint._schemas": "schemas"},
    package_data={
        "physai_lint._rules": ["*.md", "**/*.md"],
        "physai_lint._schemas": ["*.json", "**/*.json", "*.yaml", "**/*.yaml", "NOTICE*", "**/NOTICE*"],
        "physai_lint": ["data/*.json", "data/*.txt"],
    },
)
