#include "view/frame_log.h"
#include "io/output_path.h"
#include "view/viewer.h"
#include <cstdio>

namespace tf {

FrameLog::FrameLog(std::string p) : path(std::move(p))
{
    if (!path.empty())
        path = checked_output_path(path, {".csv"});
}

void FrameLog::add(const Viewer& v)
{
    if (path.empty() || frames >= 1000000) // bounded: a long session keeps its first million frames
        return;
    char row[256];
    std::snprintf(row, sizeof row, "%d,%s,%s,%s,%d,%d,%.3f,%.3f,%d,%d,%.3f\n", frames, to_string(v.state.scene).c_str(),
                  to_string(v.images.a.options.filter).c_str(),
                  v.images.has_b ? to_string(v.images.b.options.filter).c_str() : "", v.scene_width, v.scene_height,
                  v.stats.frame_ms, v.stats.render_ms, v.stats.preview_scale,
                  v.images.dynamic ? v.state.texture.texture_frame : -1, v.stats.texture_ms);
    rows += row;
    ++frames;
}

void FrameLog::write() const
{
    if (!path.empty())
        write_file_atomic(path, "frame,scene,filter_a,filter_b,width,height,frame_ms,render_ms,preview_scale,texture_frame,texture_ms\n" + rows);
}

} // namespace tf
