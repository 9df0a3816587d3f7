"""The reports' MP4 videos (report.py, formation_report.py), written once.

A frame redrawn in full (what matplotlib's writer does on each grab) draws
the 3D axes again, their panes, grid, ticks and labels: most of a report's
time went there, for pixels that do not change. The still parts are drawn
once here, and each frame draws only the artists that move over them
(blitting, matplotlib's own canvas.copy_from_bbox / restore_region)."""


def write_mp4(fig, path, fps, moving, frames, dpi=100):
    """Writes the video of `fig` to `path` (H.264, `fps` frames per second):
    each item of the iterable `frames` updates the artists `moving` (lines,
    texts of the figure), which are then drawn over the figure's still parts.
    Returns the number of frames written."""
    from matplotlib.animation import FFMpegWriter
    writer = FFMpegWriter(fps=fps, codec="libx264", extra_args=["-pix_fmt", "yuv420p"])
    count = 0
    with writer.saving(fig, path, dpi=dpi):
        canvas = fig.canvas
        sink = _frame_sink(writer, canvas)
        if sink is not None:
            for artist in moving:
                artist.set_animated(True)  # left out of the still picture
            canvas.draw()
            still = canvas.copy_from_bbox(fig.bbox)
        for _ in frames:
            if sink is None:
                writer.grab_frame()  # a writer without a pipe of raw frames: each frame redrawn in full
            else:
                canvas.restore_region(still)
                for artist in moving:
                    (artist.axes or fig).draw_artist(artist)
                sink.write(canvas.buffer_rgba())
            count += 1
    return count


def _frame_sink(writer, canvas):
    """The pipe the writer's ffmpeg reads raw RGBA frames of the canvas's
    size from (matplotlib 3.1 to 3.6 name it _proc.stdin), or None where it
    reads none, or frames of another size."""
    proc = getattr(writer, "_proc", None)
    if proc is None or getattr(writer, "frame_format", "rgba") != "rgba":
        return None
    if tuple(int(v) for v in writer.frame_size) != tuple(canvas.get_width_height()):
        return None
    return proc.stdin
