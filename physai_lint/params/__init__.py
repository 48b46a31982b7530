"""Parameter files: located model, rcl typing, structure checks, key matching, effective values."""
from .effective import Blame, EffectiveParam, effective_parameters, file_binds, matching_keys
from .loader import load_param_file
from .match import composable_key_matches, explain_no_match, key_matches
from .model import FileParam, NodeBlock, ParamFileModel, is_param_file
from .typing import pyyaml_type, rcl_type_scalar

__all__ = [
    "Blame", "EffectiveParam", "FileParam", "NodeBlock", "ParamFileModel", "composable_key_matches",
    "effective_parameters", "explain_no_match", "file_binds", "is_param_file", "key_matches",
    "load_param_file", "matching_keys", "pyyaml_type", "rcl_type_scalar",
]
