using NUnit.Framework;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>The renderer draws only on devices that run its kernels, and says why not.</summary>
    public class FluidSurfaceDeviceTests
    {
        [Test]
        public void DesktopLimits_Draw()
        {
            Assert.That(FluidSurfaceDevice.CanDraw(true, 1024, 31, out string reason), Is.True);
            Assert.That(reason, Is.Null);
        }

        [Test]
        public void LargestGroup_IsTheTileScansGroup()
        {
            Assert.That(FluidSurfaceDevice.LargestGroup, Is.EqualTo(256));
        }

        [TestCase(false, 1024, 31, "compute shaders")]
        [TestCase(true, 128, 8, "128 threads per group, the surface's tile scan uses 256")]
        [TestCase(true, 255, 31, "255 threads per group")]
        [TestCase(true, 256, 5, "5 buffers per compute kernel, the surface kernels use up to 6")]
        public void DeviceBelowTheKernelsNeeds_DoesNotDraw_AndSaysWhy(bool compute, int maxGroup, int maxBuffers, string because)
        {
            Assert.That(FluidSurfaceDevice.CanDraw(compute, maxGroup, maxBuffers, out string reason), Is.False);
            Assert.That(reason, Does.Contain(because));
        }

        [Test]
        public void OpenGlEs31Minimum_OfBuffers_IsEnough()
        {
            // GLES 3.1 guarantees 8 storage buffers per stage; the surface kernels need at most 6.
            Assert.That(FluidSurfaceDevice.CanDraw(true, 256, 8, out _), Is.True);
        }
    }
}
