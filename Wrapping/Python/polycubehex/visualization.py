# SPDX-License-Identifier: BSD-3-Clause
"""ParaView helpers (pvpython, pvbatch or the GUI's Python shell).

    from polycubehex.visualization import show_frame_glyphs
    frames = FrameField(Input=cuts)
    show_frame_glyphs(frames)       # three arrow sets: FrameU red, FrameV green, FrameW blue
"""

def white_view(size=(1200, 900)):
    """A new render view with a white background and no orientation axes, for pictures."""
    from paraview import simple

    view = simple.CreateView("RenderView")
    view.ViewSize = list(size)
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    view.Background = [1, 1, 1]
    view.OrientationAxesVisibility = 0
    return view


def show_faint_boundary(data, view, opacity=0.25):
    """Shows the boundary surface of `data` in plain grey, see-through."""
    from paraview import simple

    boundary = simple.Show(simple.ExtractSurface(Input=data), view)
    boundary.Opacity = opacity
    boundary.ColorArrayName = ["POINTS", ""]
    return boundary


def show_cuts(tets, cuts, view):
    """Shows Handle Cut's output: the model's boundary faint, each cut surface coloured by CutId,
    and the handle loops as black tubes (radius 0.3 % of the bounding-box diagonal)."""
    from paraview import simple

    show_faint_boundary(tets, view)
    surfaces = simple.Show(simple.OutputPort(cuts, 1), view)
    simple.ColorBy(surfaces, ("CELLS", "CutId"))
    bounds = tets.GetDataInformation().GetBounds()
    diagonal = sum((bounds[2 * i + 1] - bounds[2 * i]) ** 2 for i in range(3)) ** 0.5
    tubes = simple.Show(simple.Tube(Input=simple.OutputPort(cuts, 2), Radius=0.003 * diagonal),
                        view)
    tubes.ColorArrayName = ["POINTS", ""]
    tubes.DiffuseColor = [0, 0, 0]
    return surfaces


COLORS = (("FrameU", (0.85, 0.1, 0.1)), ("FrameV", (0.1, 0.65, 0.1)), ("FrameW", (0.1, 0.2, 0.9)))


def show_frame_glyphs(frame_field, view=None, scale_factor=None):
    """Shows the frame field's glyph points (output 1 of Frame Field) as three arrow glyphs,
    one per frame axis, coloured red, green and blue, sized to the spacing of the points.

    frame_field   the Frame Field proxy
    view          a render view (default: the active one)
    scale_factor  arrow length in data units (default: 0.8 of the mean spacing of the points)
    Returns the three Glyph proxies.
    """
    from paraview import simple

    view = view or simple.GetActiveViewOrCreate("RenderView")
    points = simple.OutputPort(frame_field, 1)
    frame_field.UpdatePipeline()
    info = points.GetDataInformation()
    count = max(1, info.GetNumberOfPoints())
    if scale_factor is None:
        bounds = info.GetBounds()
        extents = [max(bounds[2 * i + 1] - bounds[2 * i], 0.0) for i in range(3)]
        volume = max(extents[0] * extents[1] * extents[2], 1e-30)
        scale_factor = 0.8 * (volume / count) ** (1.0 / 3.0)
    glyphs = []
    for array, color in COLORS:
        glyph = simple.Glyph(registrationName="Frame glyphs %s" % array, Input=points,
                             GlyphType="Arrow")
        glyph.OrientationArray = ["POINTS", array]
        glyph.ScaleArray = ["POINTS", "No scale array"]
        glyph.ScaleFactor = scale_factor
        glyph.GlyphMode = "All Points"
        display = simple.Show(glyph, view)
        display.ColorArrayName = ["POINTS", ""]  # solid colour
        display.DiffuseColor = color
        display.AmbientColor = color
        glyphs.append(glyph)
    simple.Hide(points, view)
    return glyphs
