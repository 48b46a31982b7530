"""Node interfaces: interfaces files, generate_parameter_library YAML, source extraction, bundled
declarations, merged in an ``InterfaceStore``."""
from .gpl import parse_gpl, type_compatible, validate
from .model import Endpoint, NodeInterface, ParamDecl
from .store import InterfaceStore, build_interface_store, parse_interfaces_file

__all__ = ["Endpoint", "InterfaceStore", "NodeInterface", "ParamDecl", "build_interface_store",
           "parse_gpl", "parse_interfaces_file", "type_compatible", "validate"]
