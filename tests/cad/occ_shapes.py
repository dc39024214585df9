"""What the Open CASCADE checks of tests/cad share: writing a shape as STEP or IGES, and a
shape's faces as a compound."""

from OCP.BRep import BRep_Builder
from OCP.IFSelect import IFSelect_RetDone
from OCP.IGESControl import IGESControl_Writer
from OCP.STEPControl import STEPControl_AsIs, STEPControl_Writer
from OCP.TopAbs import TopAbs_FACE
from OCP.TopExp import TopExp_Explorer
from OCP.TopoDS import TopoDS_Compound


def write_step(shape, path):
    w = STEPControl_Writer()
    if w.Transfer(shape, STEPControl_AsIs) != IFSelect_RetDone or w.Write(path) != IFSelect_RetDone:
        raise RuntimeError(f"Open CASCADE could not write {path}")


def write_iges(shape, path):
    w = IGESControl_Writer("MM", 0)  # faces mode: 144 / 142 / 128
    w.AddShape(shape)
    w.ComputeModel()
    if not w.Write(path):
        raise RuntimeError(f"Open CASCADE could not write {path}")


def faces_of(shape):
    """The faces of `shape` as a compound: distances to the boundary, not to the solid (which
    is 0 inside)."""
    compound = TopoDS_Compound()
    builder = BRep_Builder()
    builder.MakeCompound(compound)
    e = TopExp_Explorer(shape, TopAbs_FACE)
    while e.More():
        builder.Add(compound, e.Current())
        e.Next()
    return compound
