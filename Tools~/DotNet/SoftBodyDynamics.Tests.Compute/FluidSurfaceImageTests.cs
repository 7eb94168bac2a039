using System;
using System.IO;
using System.Linq;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Lavapipe;
using SoftBodyDynamics.Lavapipe.Imaging;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Tests.Compute
{
    /// <summary>
    /// Image regression: each scene and look rendered on lavapipe against a checked-in PNG (RenderReferences/). A pixel
    /// differs visibly when its CIE76 ΔE exceeds 2.3 (about one just-noticeable difference); a picture fails when more than
    /// 0.2 % of its pixels do, so a changed filter, look or pass fails while round-off from another Mesa or LLVM does not.
    /// To accept a change on purpose, run the test with SBD_UPDATE_RENDER_REFERENCES=1: it rewrites the references, which
    /// are then reviewed and committed like code.
    /// </summary>
    public class FluidSurfaceImageTests
    {
        const double JustNoticeable = 2.3;
        const double VisibleShare = 0.002;

        static string ReferenceFolder() =>
            Path.Combine(Path.GetDirectoryName(Path.GetDirectoryName(LavapipeFluidSolver.ComputePath())),
                "Tools~", "DotNet", "SoftBodyDynamics.Tests.Compute", "RenderReferences");

        static readonly string[] Cases =
            SurfaceScenes.Names.Select(s => $"{s}-water").Concat(FluidLook.Presets.Skip(1).Select(p => $"two-blobs-{p.Name}")).ToArray();

        [TestCaseSource(nameof(Cases))]
        public void Picture_MatchesItsReference(string picture)
        {
            string look = FluidLook.Presets.Select(p => p.Name).First(n => picture.EndsWith("-" + n));
            FluidSurfaceScene scene = SurfaceScenes.Get(picture.Substring(0, picture.Length - look.Length - 1));
            FluidSurfaceSettings s = FluidSurfaceSettings.Desktop(scene.Radius);
            LavapipeFluidSurface.Frame f = SurfaceScenes.Render(scene, s, FluidLook.Presets.First(p => p.Name == look).Look);
            byte[] rgba = RenderImage.ToRgba(f.Over(scene.SceneColour), SurfaceScenes.Width, SurfaceScenes.Height);
            string path = Path.Combine(ReferenceFolder(), picture + ".png");
            if (Environment.GetEnvironmentVariable("SBD_UPDATE_RENDER_REFERENCES") == "1")
            {
                Directory.CreateDirectory(ReferenceFolder());
                File.WriteAllBytes(path, Png.Encode(SurfaceScenes.Width, SurfaceScenes.Height, rgba));
                TestContext.Progress.WriteLine($"reference rewritten: {path}");
            }
            Assert.That(File.Exists(path), $"no reference image {path} (run with SBD_UPDATE_RENDER_REFERENCES=1 to create it)");
            var (w, h, expected) = Png.Decode(File.ReadAllBytes(path));
            Assert.That((w, h), Is.EqualTo((SurfaceScenes.Width, SurfaceScenes.Height)), "reference size");
            double[] d = RenderImage.DeltaE(rgba, expected);
            int visible = d.Count(x => x > JustNoticeable);
            TestContext.Progress.WriteLine($"{picture}: {visible} of {d.Length} pixels differ visibly, largest ΔE {d.Max():F2}");
            if (visible > VisibleShare * d.Length)
                File.WriteAllBytes(Path.Combine(TestContext.CurrentContext.WorkDirectory, picture + ".actual.png"), Png.Encode(w, h, rgba));
            Assert.That(visible, Is.LessThanOrEqualTo((int)(VisibleShare * d.Length)), $"{picture} changed (the rendered image is in the test output folder as {picture}.actual.png)");
        }

        [Test]
        public void Png_RoundTripsAndTheDifferenceSeesAChange()
        {
            var rgba = new byte[7 * 5 * 4];
            for (int i = 0; i < rgba.Length; i++) rgba[i] = (byte)(i * 37 % 251);
            var (w, h, back) = Png.Decode(Png.Encode(7, 5, rgba));
            Assert.That((w, h), Is.EqualTo((7, 5)));
            Assert.That(back, Is.EqualTo(rgba));
            Assert.That(RenderImage.DeltaE(rgba, back).Max(), Is.Zero);
            back[0] ^= 0x40;
            Assert.That(RenderImage.DeltaE(rgba, back).Max(), Is.GreaterThan(JustNoticeable), "a changed red channel must show");
        }
    }
}
