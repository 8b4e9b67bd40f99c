#!/usr/bin/env python3
"""Renders the last frame of a run's ParaView output headless with VTK, as docs/paraview.md
describes it in ParaView: discs as glyphs scaled by radius and coloured by their mean contact
force, polygons as cells, and force chains as tubes whose radius follows fn.

    xvfb-run -a python3 docs/paraview/render.py RUN_DIR docs/paraview/force-chains.png
"""
import glob
import os
import sys

import vtk
from vtk.util.numpy_support import numpy_to_vtk, vtk_to_numpy


def last(pattern):
    files = sorted(glob.glob(pattern))
    if not files:
        sys.exit(f"no file matches {pattern}: run with --vtk first")
    return files[-1]


def reader(path):
    r = vtk.vtkXMLPolyDataReader()
    r.SetFileName(path)
    r.Update()
    return r


def force_coloured(port, lut, top):
    """An actor drawing `port`, coloured by each particle's mean contact force (0 to top)."""
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(port)
    mapper.SetLookupTable(lut)
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("mean_contact_force")
    mapper.SetScalarRange(0, top)
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    return actor


def main(run_dir, png, size=(1000, 760)):
    particles = reader(last(os.path.join(run_dir, "vtk", "particles_*.vtp")))
    contacts = reader(last(os.path.join(run_dir, "vtk", "contacts_*.vtp")))
    force_range = particles.GetOutput().GetPointData().GetArray("mean_contact_force").GetRange()

    # Discs: a unit circle glyph at each point, scaled by the point's radius (0 on polygons).
    circle = vtk.vtkRegularPolygonSource()
    circle.SetNumberOfSides(24)
    circle.SetRadius(1.0)
    glyphs = vtk.vtkGlyph3D()
    glyphs.SetInputConnection(particles.GetOutputPort())
    glyphs.SetSourceConnection(circle.GetOutputPort())
    glyphs.SetInputArrayToProcess(0, 0, 0, vtk.vtkDataObject.FIELD_ASSOCIATION_POINTS, "radius")
    glyphs.SetScaleModeToScaleByScalar()
    glyphs.SetScaleFactor(1.0)
    glyphs.SetColorModeToColorByScalar()
    glyphs.SetInputArrayToProcess(3, 0, 0, vtk.vtkDataObject.FIELD_ASSOCIATION_POINTS, "mean_contact_force")
    glyphs.Update()

    lut = vtk.vtkLookupTable()
    lut.SetHueRange(0.667, 0.0)
    lut.SetTableRange(0, force_range[1])
    lut.Build()
    discs = force_coloured(glyphs.GetOutputPort(), lut, force_range[1])


    # Polygons (elongated presets): their cells, coloured the same way.
    polygons = force_coloured(particles.GetOutputPort(), lut, force_range[1])


    # Force chains: tubes along the contact lines, radius ∝ fn (a damped contact pulling apart
    # can carry a slightly negative fn: no tube for it).
    chain_fn = vtk_to_numpy(contacts.GetOutput().GetPointData().GetArray("fn")).clip(min=0)
    mean_radius = float(vtk_to_numpy(particles.GetOutput().GetPointData().GetArray("radius")).max())
    # The strongest chain is about half a disc radius thick (or 0.6 mm without discs).
    scale = (0.5 * mean_radius if mean_radius > 0 else 0.0006) / max(chain_fn.max(initial=0), 1e-300)
    radius = numpy_to_vtk(chain_fn * scale, deep=1)
    radius.SetName("chain_radius")
    contacts.GetOutput().GetPointData().AddArray(radius)
    contacts.GetOutput().GetPointData().SetActiveScalars("chain_radius")
    tubes = vtk.vtkTubeFilter()
    tubes.SetInputData(contacts.GetOutput())
    tubes.SetVaryRadiusToVaryRadiusByAbsoluteScalar()
    tubes.SetNumberOfSides(8)
    bounds = particles.GetOutput().GetBounds()
    tube_mapper = vtk.vtkPolyDataMapper()
    tube_mapper.SetInputConnection(tubes.GetOutputPort())
    tube_mapper.ScalarVisibilityOff()
    chains = vtk.vtkActor()
    chains.SetMapper(tube_mapper)
    chains.GetProperty().SetColor(0.1, 0.1, 0.1)

    renderer = vtk.vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    for actor in (discs, polygons, chains):
        renderer.AddActor(actor)
    bar = vtk.vtkScalarBarActor()
    bar.SetLookupTable(lut)
    bar.SetTitle("mean contact force (N/m)")
    bar.GetTitleTextProperty().SetColor(0, 0, 0)
    bar.GetLabelTextProperty().SetColor(0, 0, 0)
    bar.SetNumberOfLabels(4)
    bar.SetWidth(0.08)
    bar.SetPosition(0.89, 0.1)
    renderer.AddActor2D(bar)
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(*size)
    window.AddRenderer(renderer)
    renderer.ResetCamera(bounds)
    renderer.GetActiveCamera().Zoom(1.25)
    window.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(png)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    print(f"{png}: {size[0]}x{size[1]}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
