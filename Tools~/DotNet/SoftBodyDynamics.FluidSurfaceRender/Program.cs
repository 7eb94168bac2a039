using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Lavapipe;
using SoftBodyDynamics.Lavapipe.Imaging;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

// The screen-space fluid renderer on lavapipe for the main job's report: the test scenes over the checkerboard, every
// look, the passes of one frame, and the renderer's accuracy against cost (depth and normal error against the float64
// metaball surface of the same particles, for each filter × iterations × resolution, next to the lavapipe time and the
// counted bytes per pixel). Lavapipe runs the kernels on this machine's CPU: its milliseconds rank the settings, they
// are not GPU times.
//   dotnet run -c Release --project Tools~/DotNet/SoftBodyDynamics.FluidSurfaceRender [-- --quick | --full] [--out DIR] [--gallery DIR]
// --gallery DIR also writes each look alone (fluid-look-NAME.png) and the scenes, passes and accuracy figures
// (fluid-surface-*.png) there: the documentation's images (Documentation~/images).
static class Program
{
    static readonly CultureInfo Inv = CultureInfo.InvariantCulture;

    static int Main(string[] args)
    {
        bool quick = args.Contains("--quick");
        string outDir = Arg(args, "--out") ?? Path.Combine("Reports~", "latest");
        string gallery = Arg(args, "--gallery");
        Directory.CreateDirectory(outDir);
        // Timing repeats: one in the quick run, three by default, five with --full (the images are the same).
        int repeats = quick ? 1 : args.Contains("--full") ? 5 : 3;
        var clock = Stopwatch.StartNew();
        using var device = new LavapipeDevice();
        using var surface = new LavapipeFluidSurface(device);
        var md = new StringBuilder();
        md.AppendLine($"Device: {device.DeviceName} ({Environment.ProcessorCount} cores). Lavapipe is a CPU driver: its times rank settings against each other, they are not GPU times.");
        md.AppendLine();

        // Scenes, lit water: the sphere, the two blobs behind an opaque post, a dam-break frame of the CPU solver.
        int w = quick ? 320 : 480, h = quick ? 180 : 270;
        var scenes = FluidSurfaceScene.All(w, h);
        var row = new List<byte[]>();
        foreach (FluidSurfaceScene scene in scenes)
            row.Add(Picture(surface, scene, FluidSurfaceSettings.Desktop(scene.Radius), FluidLook.Water).Rgba);
        Save(outDir, "surface-scenes.png", Montage(row, w, h, scenes.Length));
        md.AppendLine($"![scenes](surface-scenes.png)").AppendLine();
        md.AppendLine($"*{w}×{h}, desktop settings (full-resolution depth, narrow-range filter, one iteration), water: one ball of {scenes[0].Particles.Length} particles; two balls ({scenes[1].Particles.Length}) behind an opaque post; the CPU solver's dam break after 0.08 s ({scenes[2].Particles.Length} particles).*").AppendLine();

        // Every look on the two blobs.
        int gw = 320, gh = 180;
        FluidSurfaceScene blobs = FluidSurfaceScene.TwoBlobs(gw, gh);
        var looks = new List<byte[]>();
        foreach (var (name, look) in FluidLook.Presets)
        {
            var (rgba, _) = Picture(surface, blobs, FluidSurfaceSettings.Desktop(blobs.Radius), look);
            looks.Add(rgba);
            if (gallery != null)
            {
                Directory.CreateDirectory(gallery);
                File.WriteAllBytes(Path.Combine(gallery, $"fluid-look-{name}.png"), Png.Encode(gw, gh, rgba));
            }
        }
        Save(outDir, "surface-looks.png", Montage(looks, gw, gh, 4));
        md.AppendLine("![looks](surface-looks.png)").AppendLine();
        md.AppendLine("*The looks, left to right and top to bottom: " + string.Join(", ", FluidLook.Presets.Select(p => p.Name)) + " (lava's temperature is the particle attribute, hotter low in each ball).*").AppendLine();

        // The passes of one frame.
        FluidSurfaceScene dam = scenes[2];
        FluidSurfaceSettings desktop = FluidSurfaceSettings.Desktop(dam.Radius);
        var (finalRgba, f) = Picture(surface, dam, desktop, FluidLook.Water);
        float zMin = f.RawDepth.Where(z => z > 0f).DefaultIfEmpty(1f).Min(), zMax = f.RawDepth.Where(z => z > 0f).DefaultIfEmpty(1f).Max();
        var passImages = new List<byte[]>
        {
            RenderImage.ToRgba(RenderImage.Ramp(f.RawDepth, zMax, zMin), w, h),
            RenderImage.ToRgba(RenderImage.Ramp(f.Depth, zMax, zMin), w, h),
            RenderImage.ToRgba(NormalColours(f), w, h),
            RenderImage.ToRgba(RenderImage.Ramp(Upsample(f.Thickness.Select(t => t.x).ToArray(), f.Targets.Thickness, w, h), 0f, 10f * dam.Radius), w, h),
            finalRgba,
        };
        Save(outDir, "surface-passes.png", Montage(passImages, w, h, 5));
        md.AppendLine("![passes](surface-passes.png)").AppendLine();
        md.AppendLine("*One frame's passes: splatted depth (near is white), narrow-range-filtered depth (one iteration), normals (view space as colour), thickness at half resolution (white at 10 radii), the composite.*").AppendLine();

        // The two tiers side by side.
        var (mobileRgba, _) = Picture(surface, dam, FluidSurfaceSettings.Mobile(dam.Radius), FluidLook.Water);
        Save(outDir, "surface-tiers.png", Montage(new List<byte[]> { finalRgba, mobileRgba }, w, h, 2));
        md.AppendLine("![tiers](surface-tiers.png)").AppendLine();
        md.AppendLine("*The dam-break frame in the desktop tier (left: depth, smoothing, normals and composite at full resolution) and the mobile tier (right: all at half resolution, the composite upsampled bilinearly by the overlay).*").AppendLine();

        // Cost table of the two tiers.
        md.AppendLine("### Counted memory traffic per screen pixel").AppendLine();
        FluidSurfaceSettings mobile = FluidSurfaceSettings.Mobile(dam.Radius);
        md.AppendLine("| pass (water) | desktop (full resolution) B/px | mobile (half-resolution depth and composite) B/px |");
        md.AppendLine("|---|---|---|");
        var dc = FluidSurfaceCost.Passes(desktop, FluidLook.Water);
        var mc = FluidSurfaceCost.Passes(mobile, FluidLook.Water);
        foreach (FluidSurfacePassCost p in dc)
        {
            double m = mc.Where(q => q.Stage == p.Stage).Select(q => q.BytesPerPixel).DefaultIfEmpty(0).First();
            md.AppendLine($"| {p.Pass.Split(" (")[0]} | {p.BytesPerPixel.ToString("0.#", Inv)} | {m.ToString("0.#", Inv)} |");
        }
        md.AppendLine($"| **total** | **{FluidSurfaceCost.BytesPerPixel(desktop, FluidLook.Water).ToString("0.#", Inv)}** | **{FluidSurfaceCost.BytesPerPixel(mobile, FluidLook.Water).ToString("0.#", Inv)}** |");
        double entries = f.Stats[FluidSurfaceLayout.StatEntries] / (double)Math.Max(1, f.Stats[FluidSurfaceLayout.StatDrawn]);
        md.AppendLine();
        md.AppendLine($"Tile binning adds {FluidSurfaceCost.BinningBytesPerParticle(entries).ToString("0", Inv)} B per particle in the dam-break frame ({entries.ToString("0.00", Inv)} tile entries per particle).").AppendLine();

        // Accuracy against cost.
        md.AppendLine("### Accuracy against cost").AppendLine();
        md.AppendLine("Error of the smoothed depth and of the normals against the float64 metaball iso-surface of the same particles (φ = Σ(1 − d²/R²)³, R = 2r, through each particle's own sphere when alone), over the pixels both cover, in particle radii r and degrees; coverage mismatch is the share of pixels covered by only one of the two. Time: lavapipe, whole frame, median of " + repeats + ".").AppendLine();
        int aw = quick ? 160 : 320, ah = quick ? 90 : 180;
        var accuracyScenes = quick ? new[] { FluidSurfaceScene.Sphere(aw, ah) } : FluidSurfaceScene.All(aw, ah);
        var configs = Configurations(quick);
        md.AppendLine($"{aw}×{ah} screen. Union-of-spheres check: the raw splat's depth against the float64 union of the spheres (exact to float32 round-off by construction).").AppendLine();
        md.AppendLine("| scene | filter | iterations | depth | lavapipe ms | B/px | depth error mean / p95 (r) | normal error mean / p95 (°) | coverage mismatch |");
        md.AppendLine("|---|---|---|---|---|---|---|---|---|");
        var points = new List<(string Series, double Bytes, double Angle, double Depth, string Label)>();
        foreach (FluidSurfaceScene scene in accuracyScenes)
        {
            var references = new Dictionary<int, FluidSurfaceReference.Surface>
            {
                [1] = FluidSurfaceReference.Metaball(scene, 1),
                [2] = FluidSurfaceReference.Metaball(scene, 2),
            };
            FluidSurfaceReference.Surface union = FluidSurfaceReference.UnionOfSpheres(scene, 1);
            foreach (var (filter, iterations, divisor) in configs)
            {
                FluidSurfaceSettings s = divisor == 1 ? FluidSurfaceSettings.Desktop(scene.Radius) : FluidSurfaceSettings.Mobile(scene.Radius);
                s.Filter = filter;
                s.Iterations = iterations;
                var times = new List<double>();
                LavapipeFluidSurface.Frame frame = null;
                for (int r = 0; r <= repeats; r++)
                {
                    frame = surface.Render(scene.Camera, s, FluidLook.Water, scene.Lighting, scene.Particles, scene.SceneColour, scene.SceneEyeDepth);
                    if (r > 0) times.Add(frame.TotalMs);
                }
                double ms = Median(times);
                var e = FluidSurfaceReference.Compare(references[divisor], frame.Depth, frame.Normals, scene.Radius);
                string res = divisor == 1 ? "full" : "half";
                md.AppendLine($"| {scene.Name} | {Name(filter)} | {iterations} | {res} | {ms.ToString("0.0", Inv)} | {FluidSurfaceCost.BytesPerPixel(s, FluidLook.Water).ToString("0.#", Inv)} | {e.MeanDepth.ToString("0.000", Inv)} / {e.P95Depth.ToString("0.00", Inv)} | {e.MeanAngle.ToString("0.0", Inv)} / {e.P95Angle.ToString("0.0", Inv)} | {e.CoverageMismatch.ToString("P1", Inv)} |");
                if (filter == FluidSurfaceFilter.None && divisor == 1)
                {
                    var u = FluidSurfaceReference.Compare(union, frame.RawDepth, frame.Normals, scene.Radius);
                    md.AppendLine($"| {scene.Name} | raw splat vs union of spheres | – | full | – | – | {u.MeanDepth.ToString("0.0e0", Inv)} / {u.P95Depth.ToString("0.0e0", Inv)} | – | {u.CoverageMismatch.ToString("P2", Inv)} |");
                }
                if (scene == accuracyScenes[^1])
                    points.Add(($"{Name(filter)}, {res}", FluidSurfaceCost.BytesPerPixel(s, FluidLook.Water), e.MeanAngle, e.MeanDepth, filter == FluidSurfaceFilter.None ? "" : iterations.ToString(Inv)));
            }
        }
        md.AppendLine();
        string plot = Plot(outDir, accuracyScenes[^1].Name, points);
        if (plot != null)
            md.AppendLine($"![accuracy against cost]({plot})").AppendLine();
        else
            md.AppendLine("*Figure skipped: gnuplot not found.*").AppendLine();
        if (gallery != null)
            foreach (string name in new[] { "surface-scenes.png", "surface-passes.png", "surface-tiers.png", "surface-accuracy.png" })
                if (File.Exists(Path.Combine(outDir, name)))
                    File.Copy(Path.Combine(outDir, name), Path.Combine(gallery, "fluid-" + name), true);
        md.AppendLine($"*Written in {clock.Elapsed.TotalSeconds.ToString("0", Inv)} s.*");
        File.WriteAllText(Path.Combine(outDir, "surface.md"), md.ToString());
        Console.WriteLine(md.ToString());
        return 0;
    }

    static string Arg(string[] args, string name)
    {
        int i = Array.IndexOf(args, name);
        return i >= 0 && i + 1 < args.Length ? args[i + 1] : null;
    }

    static string Name(FluidSurfaceFilter f) => f switch
    {
        FluidSurfaceFilter.None => "none",
        FluidSurfaceFilter.NarrowRange => "narrow-range",
        FluidSurfaceFilter.Bilateral => "bilateral",
        _ => "curvature flow",
    };

    static List<(FluidSurfaceFilter, int, int)> Configurations(bool quick)
    {
        var list = new List<(FluidSurfaceFilter, int, int)>();
        foreach (int divisor in new[] { 1, 2 })
        {
            list.Add((FluidSurfaceFilter.None, 0, divisor));
            foreach (int it in quick ? new[] { 1 } : new[] { 1, 2, 4 })
            {
                list.Add((FluidSurfaceFilter.NarrowRange, it, divisor));
                if (!quick) list.Add((FluidSurfaceFilter.Bilateral, it, divisor));
            }
            foreach (int it in quick ? new[] { 10 } : new[] { 10, 20, 40 })
                list.Add((FluidSurfaceFilter.CurvatureFlow, it, divisor));
        }
        return list;
    }

    static (byte[] Rgba, LavapipeFluidSurface.Frame Frame) Picture(LavapipeFluidSurface surface, FluidSurfaceScene scene, FluidSurfaceSettings settings, FluidLook look)
    {
        LavapipeFluidSurface.Frame f = surface.Render(scene.Camera, settings, look, scene.Lighting, scene.Particles, scene.SceneColour, scene.SceneEyeDepth);
        return (RenderImage.ToRgba(f.Over(scene.SceneColour), scene.Camera.Width, scene.Camera.Height), f);
    }

    static float4[] NormalColours(LavapipeFluidSurface.Frame f)
    {
        var c = new float4[f.Normals.Length];
        for (int i = 0; i < c.Length; i++)
        {
            float3 n = FluidSurfacePasses.UnpackNormal(f.Normals[i]);
            // Shown in sRGB: undo the encoding so 0.5 + 0.5 n is what the PNG holds.
            c[i] = f.Depth[i] > 0f ? new float4(Linear(0.5f + 0.5f * n.x), Linear(0.5f + 0.5f * n.y), Linear(0.5f + 0.5f * n.z), 1f) : new float4(0.02f, 0.02f, 0.06f, 1f);
        }
        return c;
    }

    static float Linear(float s) => s <= 0.04045f ? s / 12.92f : (float)Math.Pow((s + 0.055) / 1.055, 2.4);

    static float[] Upsample(float[] half, int2 size, int w, int h)
    {
        var full = new float[w * h];
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++)
                full[y * w + x] = half[Math.Min(y / 2, size.y - 1) * size.x + Math.Min(x / 2, size.x - 1)];
        return full;
    }

    /// <summary>Images of w × h in a grid of <paramref name="columns"/>, left to right then top to bottom.</summary>
    static (int Width, int Height, byte[] Rgba) Montage(List<byte[]> images, int w, int h, int columns)
    {
        int rows = (images.Count + columns - 1) / columns;
        var sheet = new byte[columns * w * rows * h * 4];
        for (int k = 0; k < images.Count; k++)
        {
            int ox = k % columns * w, oy = k / columns * h;
            for (int y = 0; y < h; y++)
                Buffer.BlockCopy(images[k], y * w * 4, sheet, ((oy + y) * columns * w + ox) * 4, w * 4);
        }
        return (columns * w, rows * h, sheet);
    }

    static void Save(string dir, string name, (int Width, int Height, byte[] Rgba) image) =>
        File.WriteAllBytes(Path.Combine(dir, name), Png.Encode(image.Width, image.Height, image.Rgba));

    static double Median(List<double> v)
    {
        var s = v.OrderBy(x => x).ToList();
        return s.Count % 2 == 1 ? s[s.Count / 2] : 0.5 * (s[s.Count / 2 - 1] + s[s.Count / 2]);
    }

    static string Plot(string dir, string scene, List<(string Series, double Bytes, double Angle, double Depth, string Label)> points)
    {
        string path = Environment.GetEnvironmentVariable("PATH") ?? "";
        if (!path.Split(':').Any(d => File.Exists(Path.Combine(d, "gnuplot"))))
            return null;
        const string name = "surface-accuracy";
        var dat = new StringBuilder();
        var plots = new List<string>();
        int index = 0;
        foreach (var g in points.GroupBy(p => p.Series))
        {
            foreach (var p in g.OrderBy(p => p.Bytes))
                dat.AppendLine(string.Format(Inv, "{0:G6} {1:G6} {2:G6} \"{3}\"", p.Bytes, p.Angle, p.Depth, p.Label));
            dat.AppendLine().AppendLine();
            string dash = g.Key.EndsWith("half") ? "dt 2" : "dt 1";
            plots.Add($"'{name}.dat' index {index} using 1:2 with linespoints lt {index / 2 % 8 + 1} {dash} pt {5 + index % 2} ps 1.2 title '{g.Key}'");
            plots.Add($"'{name}.dat' index {index} using 1:2:4 with labels offset 0.6,0.5 left font ',8' notitle");
            index++;
        }
        File.WriteAllText(Path.Combine(dir, name + ".dat"), dat.ToString());
        string gp = $@"set terminal pngcairo size 960,560 font ',10'
set output '{name}.png'
set title 'Fluid surface ({scene}): normal error against the metaball surface vs memory traffic (labels: iterations)'
set xlabel 'counted bytes per screen pixel'
set ylabel 'mean normal error (degrees)'
set logscale x
set grid
set key outside right top
plot {string.Join(", ", plots)}
";
        File.WriteAllText(Path.Combine(dir, name + ".gp"), gp);
        var psi = new ProcessStartInfo("gnuplot", name + ".gp") { WorkingDirectory = dir, RedirectStandardError = true, UseShellExecute = false };
        using Process gnuplot = Process.Start(psi);
        string err = gnuplot.StandardError.ReadToEnd();
        gnuplot.WaitForExit();
        if (gnuplot.ExitCode != 0)
        {
            Console.Error.WriteLine("gnuplot: " + err);
            return null;
        }
        return name + ".png";
    }
}
