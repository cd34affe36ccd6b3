// firsthit accuracy FILE: what accuracy costs in time. Renders a reference
// (double, 256 samples per pixel, depth 16, or deeper where 16 has not
// converged), then sweeps each knob, and reports time, rays and error against
// the reference per setting, as a CSV and a plot.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include <unistd.h>

#include "cli/commands.h"
#include "cli/job.h"
#include "files/atomic_file.h"
#include "files/file_names.h"
#include "files/input_files.h"
#include "text/input_error.h"
#include "render/accuracy_sweep.h"

namespace fh {

namespace {

std::string number(double v) {
    if (std::isinf(v)) return "inf";
    std::ostringstream s;
    s.precision(6);
    s << v;
    return s.str();
}

void write_csv(std::ostream& out, const std::vector<AccuracyRow>& rows) {
    out << "setting,spp,adaptive,depth,precision,ms,rays,rmse,psnr,max_error,refined_pixels,"
           "isolated_rmse,isolated_psnr,mipmaps\n";
    for (const AccuracyRow& r : rows) {
        const RenderSettings& s = r.settings;
        out << r.knob << "," << (s.adaptive ? s.adaptive_samples : s.samples_per_pixel) << ","
            << (s.adaptive ? 1 : 0) << "," << s.max_depth << "," << precision_name(s.precision)
            << "," << number(r.ms) << "," << r.rays << "," << number(r.error.rmse) << ","
            << number(r.error.psnr) << "," << r.error.max_error << "," << r.refined_pixels << ","
            << number(r.isolated.rmse) << "," << number(r.isolated.psnr) << "," << (s.mipmaps ? 1 : 0) << "\n";
    }
}

// Error (PSNR, capped for identical images) against time, one curve per knob.
void plot(const std::string& csv, const std::string& png, const std::string& title) {
    std::FILE* gp = popen("gnuplot 2>&1", "w");
    if (!gp) throw std::runtime_error("cannot run gnuplot; install it with: apt-get install gnuplot-nox");
    std::fprintf(gp, R"(set terminal pngcairo size 1280,560 font ",11"
set output '%s'
set datafile separator ','
set multiplot layout 1,2 title "%s"
set xlabel 'median render time (ms, log scale)'
set logscale x
set grid
set key bottom right
psnr(c) = (strcol(c) eq 'inf') ? 100 : column(c)
set title 'anti-aliasing: error against the reference (256 samples)'
set ylabel 'PSNR (dB, higher is better)'
plot '%s' using (strcol(1) eq 'spp' ? $6 : 1/0):(psnr(9)) with linespoints lw 2 pt 7 title 'samples per pixel (uniform)', \
     '' using (strcol(1) eq 'spp' ? $6 : 1/0):(psnr(9)):2 with labels offset 0,1 notitle, \
     '' using (strcol(1) eq 'adaptive' ? $6 : 1/0):(psnr(9)) with linespoints lw 2 pt 5 title 'adaptive (max samples)', \
     '' using (strcol(1) eq 'adaptive' ? $6 : 1/0):(psnr(9)):2 with labels offset 0,-1 notitle, \
     '' using (strcol(1) eq 'mipmaps' ? $6 : 1/0):(psnr(9)) with points pt 11 ps 2 title 'textures, 1 sample: mipmaps (1) or none (0)', \
     '' using (strcol(1) eq 'mipmaps' ? $6 : 1/0):(psnr(9)):14 with labels offset 2,0 notitle
set title 'depth and precision: error against a 1-sample reference (PSNR 100 = identical)'
set yrange [*:105]
plot '%s' using (strcol(1) eq 'depth' ? $6 : 1/0):(psnr(13)) with linespoints lw 2 pt 9 title 'glazing depth 0..8', \
     '' using (strcol(1) eq 'depth' ? $6 : 1/0):(psnr(13)):4 with labels offset 0,1 notitle, \
     '' using (strcol(1) eq 'precision' ? $6 : 1/0):(psnr(13)) with points pt 13 ps 2 title 'float vs double (depth as the file)', \
     '' using (strcol(1) eq 'precision' ? $6 : 1/0):(psnr(13)):5 with labels offset 3,0 notitle
unset multiplot
)",
                 png.c_str(), title.c_str(), csv.c_str(), csv.c_str());
    if (pclose(gp) != 0)
        throw std::runtime_error("gnuplot failed to plot " + png +
                                 " (is it installed? apt-get install gnuplot-nox)");
}

// --csv OUT.csv and --plot OUT.png, checked before the sweep's minutes of
// rendering: the right extensions, places that can be written, and (once the
// scene is read) none of its files.
void check_outputs(const Args& args) {
    const auto csv = args.value("--csv"), png = args.value("--plot");
    if (png && !csv) throw UsageError("--plot needs --csv (gnuplot reads the table from it)");
    if (csv && lowercase_extension(*csv) != ".csv")
        throw UsageError("--csv " + *csv + ": the table's name must end in .csv");
    if (png && lowercase_extension(*png) != ".png")
        throw UsageError("--plot " + *png + ": the plot's name must end in .png");
    for (const auto& out : {csv, png})
        if (out) check_output_file(*out);
}

}  // namespace

int run_accuracy(const Args& args) {
    check_outputs(args);
    const Job job = job_from_args(args);
    for (const auto& out : {args.value("--csv"), args.value("--plot")})
        if (out) check_not_an_input(*out);
    AccuracyOptions options;
    options.runs = args.integer("--runs", 3, 1, 1000);
    options.reference_spp = args.integer("--reference-spp", 256, 1, Limits::max_samples_per_pixel);
    options.max_spp = args.integer("--max-spp", 64, 1, Limits::max_samples_per_pixel);
    if (options.reference_spp < options.max_spp)
        throw UsageError("--reference-spp " + std::to_string(options.reference_spp) + " is below --max-spp " +
                         std::to_string(options.max_spp) + ": the reference must have the most samples");
    ThreadPool pool(args.integer("--threads", 0, 0, 1024));

    const bool tty = isatty(STDERR_FILENO);
    const AccuracyReport report = sweep_accuracy(
        job.scene(), job.camera, job.settings(), options, pool,
        [&](int depth) {
            std::cerr << "accuracy: reference " << options.reference_spp << " samples per pixel, depth " << depth
                      << ", double\n";
        },
        [&](int rows) {
            if (tty) std::cerr << "\raccuracy: " << rows << " settings measured" << std::flush;
        });
    const std::vector<AccuracyRow>& rows = report.rows;
    if (tty) std::cerr << "\n";

    const auto csv = args.value("--csv");
    if (csv) {
        std::ostringstream table;
        write_csv(table, rows);
        const std::string text = table.str();
        write_file_atomic(*csv, std::vector<std::uint8_t>(text.begin(), text.end()));
    } else {
        write_csv(std::cout, rows);
    }
    if (const auto png = args.value("--plot")) {
        std::string title = job.file + (job.frame >= 0 ? " frame " + std::to_string(job.frame) : "");
        // gnuplot writes as it goes: to a temporary, renamed once whole.
        const std::string part = temporary_name(*png, 0);
        try {
            plot(*csv, part, "What accuracy costs: " + title);
        } catch (...) {
            std::remove(part.c_str());
            throw;
        }
        if (std::rename(part.c_str(), png->c_str()) != 0) {
            std::remove(part.c_str());
            throw std::runtime_error("cannot write " + *png);
        }
    }
    return 0;
}

}  // namespace fh
