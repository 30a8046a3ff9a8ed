"""The library, loaded once (see _library), and the ctypes declaration of every function of
lfem.h. The functions that return lfem_status raise LfemError when it is not LFEM_OK."""

from __future__ import annotations

import ctypes
from typing import Any

from . import _errors, _library, _structs
from ._structs import (Attachment, AttachmentDef, Body, BodyDef, Event, Profile, QueryFilter, RayHit,
                       ShapeDef, Warning, WorldDef,
                       WorldStats)

lib, library_path = _library.load()


def c_string(pointer: Any) -> str:
    return pointer.decode("utf-8", "replace") if pointer is not None else ""


def _errcheck(result: int, func: Any, args: Any) -> int:
    if result != 0:
        raise _errors.error(result, c_string(lib.lfem_last_error()))
    return result


_p = ctypes.POINTER
_dp = _p(ctypes.c_double)
_up = _p(ctypes.c_uint32)
_vp = ctypes.c_void_p
_u32 = ctypes.c_uint32
_dbl = ctypes.c_double
_enum = ctypes.c_int
_st = object()  # marks functions returning lfem_status (a C int): they raise LfemError


def _declare(name: str, restype: Any, *argtypes: Any) -> None:
    f = getattr(lib, name)
    f.argtypes = list(argtypes)
    if restype is _st:
        f.restype = ctypes.c_int
        f.errcheck = _errcheck
    else:
        f.restype = restype


_declare("lfem_status_string", ctypes.c_char_p, _enum)
_declare("lfem_last_error", ctypes.c_char_p)
_declare("lfem_version", _u32)
_declare("lfem_version_string", ctypes.c_char_p)

_declare("lfem_world_def_default", WorldDef)
_declare("lfem_world_create", _st, _p(WorldDef), _p(_vp))
_declare("lfem_world_destroy", None, _vp)
_declare("lfem_world_step", _st, _vp, _dbl)
_declare("lfem_world_save", _st, _vp, ctypes.c_char_p)
_declare("lfem_world_load", _st, ctypes.c_char_p, _p(_vp))
_declare("lfem_world_set_gravity", _st, _vp, _dp)
_declare("lfem_world_set_time_step", _st, _vp, _dbl)
_declare("lfem_world_get_stable_step", _st, _vp, _dp)
_declare("lfem_world_get_stats", _st, _vp, _p(WorldStats))
_declare("lfem_world_get_profile", _st, _vp, _p(Profile))
_declare("lfem_world_reset_profile", _st, _vp)
_declare("lfem_world_get_warning", _st, _vp, _enum, _p(Warning))
_declare("lfem_world_clear_warnings", _st, _vp)
_declare("lfem_world_get_events", _st, _vp, _p(Event), _u32, _up)
_declare("lfem_attachment_def_default", AttachmentDef)
_declare("lfem_attachment_create", _st, _vp, _p(AttachmentDef), _p(Attachment))
_declare("lfem_attachment_destroy", _st, _vp, Attachment)
_declare("lfem_attachment_is_valid", ctypes.c_int, _vp, Attachment)
_declare("lfem_attachment_set_frame", _st, _vp, Attachment, _dp)
_declare("lfem_attachment_get_force", _st, _vp, Attachment, _dp)
_declare("lfem_body_wake", _st, _vp, Body)
_declare("lfem_body_is_awake", ctypes.c_int, _vp, Body)

_declare("lfem_body_def_default", BodyDef)
_declare("lfem_body_create", _st, _vp, _p(BodyDef), _p(Body))
_declare("lfem_body_destroy", _st, _vp, Body)
_declare("lfem_body_is_valid", ctypes.c_int, _vp, Body)
_declare("lfem_body_add_mesh", _st, _vp, Body, _dp, _u32, _up, _u32)
_declare("lfem_body_add_quadratic_mesh", _st, _vp, Body, _dp, _u32, _up, _u32)
_declare("lfem_body_get_node_count", _st, _vp, Body, _up)
_declare("lfem_body_get_tet_count", _st, _vp, Body, _up)
_declare("lfem_body_get_nodes_per_tet", _st, _vp, Body, _up)
_declare("lfem_body_get_user_data", _st, _vp, Body, _p(_vp))
_declare("lfem_body_get_mass", _st, _vp, Body, _dp)
_declare("lfem_body_get_added_mass", _st, _vp, Body, _dp)
_declare("lfem_body_get_inversion", _st, _vp, Body, _up, _dp, _dp)
_declare("lfem_body_get_momentum", _st, _vp, Body, _dp, _dp)
_declare("lfem_body_get_positions", _st, _vp, Body, _dp, _u32)
_declare("lfem_body_get_velocities", _st, _vp, Body, _dp, _u32)
_declare("lfem_body_set_velocities", _st, _vp, Body, _dp, _u32)
_declare("lfem_body_get_boundary_triangle_count", _st, _vp, Body, _up)
_declare("lfem_body_get_boundary_triangles", _st, _vp, Body, _up, _u32)
_declare("lfem_body_get_boundary_face_count", _st, _vp, Body, _up)
_declare("lfem_body_get_boundary_faces", _st, _vp, Body, _up, _u32)
_declare("lfem_body_get_von_mises_stress", _st, _vp, Body, _dp, _u32)
_declare("lfem_body_get_rotation", _st, _vp, Body, _dp)
_declare("lfem_body_set_positions", _st, _vp, Body, _dp, _u32)
_declare("lfem_body_apply_impulse", _st, _vp, Body, _dp, _dp)
_declare("lfem_body_apply_force", _st, _vp, Body, _dp, _dp)
_declare("lfem_body_set_user_id", _st, _vp, Body, ctypes.c_uint64)
_declare("lfem_body_set_type", _st, _vp, Body, _enum)
_declare("lfem_body_get_type", _st, _vp, Body, _p(_enum))
_declare("lfem_body_get_user_id", _st, _vp, Body, _p(ctypes.c_uint64))
_declare("lfem_body_set_friction", _st, _vp, Body, ctypes.c_double)
_declare("lfem_body_set_damping", _st, _vp, Body, ctypes.c_double)
_declare("lfem_body_set_sleep_allowed", _st, _vp, Body, ctypes.c_int)
_declare("lfem_attachment_get_frame", _st, _vp, Attachment, _dp)
_declare("lfem_body_set_material", _st, _vp, Body, ctypes.c_double, ctypes.c_double)
_declare("lfem_body_set_filter", _st, _vp, Body, _u32, _u32)
_declare("lfem_body_set_user_data", _st, _vp, Body, _vp)
_declare("lfem_body_remove_skin", _st, _vp, Body, _u32)
_declare("lfem_body_get_transform", _st, _vp, Body, _dp)
_declare("lfem_body_closest_point", _st, _vp, Body, _dp, _dp, ctypes.POINTER(_u32), _dp)
_declare("lfem_body_set_transform", _st, _vp, Body, _dp)
_declare("lfem_body_get_center_of_mass", _st, _vp, Body, _dp)
_declare("lfem_body_find_nodes_in_box", _st, _vp, Body, _dp, _dp, _up, _u32, _up)
_declare("lfem_body_fix_nodes", _st, _vp, Body, _up, _u32)
_declare("lfem_body_prescribe_node_velocity", _st, _vp, Body, _up, _u32, _dp)
_declare("lfem_body_release_nodes", _st, _vp, Body, _up, _u32)
_declare("lfem_body_set_node_forces", _st, _vp, Body, _up, _u32, _dp)
_declare("lfem_body_clear_node_forces", _st, _vp, Body)
_declare("lfem_body_set_kinematic_velocity", _st, _vp, Body, _dp, _dp)

_declare("lfem_shape_def_default", ShapeDef)
_declare("lfem_body_add_shape", _st, _vp, Body, _p(ShapeDef), _up)

_declare("lfem_world_query_contacts", _st, _vp, _vp, _u32, _up)

_fp = _p(ctypes.c_float)
_declare("lfem_body_add_skin", _st, _vp, Body, _dp, _u32, _up, _u32, _up)
_declare("lfem_body_get_skin_count", _st, _vp, Body, _up)
_declare("lfem_body_get_skin_sizes", _st, _vp, Body, _u32, _up, _up)
_declare("lfem_body_get_skin_triangles", _st, _vp, Body, _u32, _up, _u32)
_declare("lfem_body_get_skin_vertices", _st, _vp, Body, _u32, _dp, _dp, _u32)
_declare("lfem_body_get_skin_vertices_f32", _st, _vp, Body, _u32, _fp, _u32, _fp, _u32, _u32)

_declare("lfem_query_filter_default", QueryFilter)
_declare("lfem_world_cast_ray", _st, _vp, _dp, _dp, _dbl, QueryFilter, _p(RayHit),
         _p(ctypes.c_int))
_declare("lfem_world_cast_sphere", _st, _vp, _dp, _dp, _dbl, _dbl, QueryFilter, _p(RayHit),
         _p(ctypes.c_int))
_declare("lfem_world_cast_ray_all", _st, _vp, _dp, _dp, _dbl, QueryFilter, _vp, _u32, _up)
_declare("lfem_world_overlap_capsule", _st, _vp, _dp, _dp, _dbl, QueryFilter, _vp, _u32, _up)
_declare("lfem_world_overlap_box", _st, _vp, _dp, _dp, QueryFilter, _vp, _u32, _up)

_declare("lfem_mesh_create_box", _st, _dp, _up, _p(_vp))
_declare("lfem_mesh_create_cylinder", _st, _dbl, _dbl, _u32, _u32, _u32, _p(_vp))
_declare("lfem_mesh_create_cup", _st, _dbl, _dbl, _dbl, _dbl, _u32, _u32, _p(_vp))
_declare("lfem_mesh_create_hammer", _st, _dbl, _dbl, _dbl, _dbl, _dbl, _p(_vp))
_declare("lfem_mesh_load_gmsh", _st, ctypes.c_char_p, _p(_vp))
_declare("lfem_mesh_make_quadratic", _st, _vp)
_declare("lfem_mesh_get_nodes_per_tet", _u32, _vp)
_declare("lfem_mesh_destroy", None, _vp)
_declare("lfem_mesh_get_node_count", _u32, _vp)
_declare("lfem_mesh_get_tet_count", _u32, _vp)
_declare("lfem_mesh_get_positions", _dp, _vp)
_declare("lfem_mesh_get_tets", _up, _vp)
_declare("lfem_mesh_translate", _st, _vp, _dp)
_declare("lfem_mesh_rotate", _st, _vp, _dp, _dbl)

_declare("lfem_vtk_series_create", _st, ctypes.c_char_p, _p(_vp))
_declare("lfem_vtk_series_write_frame", _st, _vp, _vp)
_declare("lfem_vtk_series_destroy", None, _vp)

_structs.DEFAULTS[WorldDef] = lib.lfem_world_def_default
_structs.DEFAULTS[BodyDef] = lib.lfem_body_def_default
_structs.DEFAULTS[ShapeDef] = lib.lfem_shape_def_default
_structs.DEFAULTS[QueryFilter] = lib.lfem_query_filter_default
