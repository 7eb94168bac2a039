using System;
using System.IO;
using System.Linq;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Lavapipe;
using SoftBodyDynamics.Lavapipe.Imaging;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

static class Program
{
    static int Main(string[] args)
    {
        string outDir = args.Length > 0 ? args[0] : "/tmp/surface";
        Directory.CreateDirectory(outDir);
        using var device = new LavapipeDevice();
        using var surface = new LavapipeFluidSurface(device);
        foreach (var scene in FluidSurfaceScene.All(320, 180))
        {
            Console.WriteLine($"{scene.Name}: {scene.Particles.Length} particles");
            foreach (var (name, look) in FluidLook.Presets)
            {
                var settings = FluidSurfaceSettings.Desktop(scene.Radius);
                var f = surface.Render(scene.Camera, settings, look, scene.Lighting, scene.Particles, scene.SceneColour, scene.SceneEyeDepth);
                var img = RenderImage.Over(f.Colour, scene.SceneColour);
                File.WriteAllBytes(Path.Combine(outDir, $"{scene.Name}-{name}.png"), Png.Encode(320, 180, RenderImage.ToRgba(img, 320, 180)));
                Console.WriteLine($"  {name}: {f.TotalMs:F1} ms entries {f.Stats[0]} drawn {f.Stats[2]} regrow {surface.Regrowths}");
            }
        }
        return 0;
    }
}
