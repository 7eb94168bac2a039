using NUnit.Framework;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Tests.Solvers
{
    public class FluidBackendChoiceTests
    {
        [Test]
        public void Cpu_IsNeverTheGpu()
        {
            Assert.That(FluidBackendChoice.UseGpu(FluidBackend.Cpu, true, true, 1024, 31, out string reason), Is.False);
            Assert.That(reason, Is.Null);
        }

        [TestCase(FluidBackend.Auto)]
        [TestCase(FluidBackend.Gpu)]
        public void GpuOrAuto_TakesTheGpuWhenEverythingIsThere(FluidBackend requested)
        {
            Assert.That(FluidBackendChoice.UseGpu(requested, true, true, 256, FluidComputeLayout.MaxBuffersPerKernel, out string reason), Is.True);
            Assert.That(reason, Is.Null);
        }

        [TestCase(false, true, 1024, 31, "compute shaders")]
        [TestCase(true, false, 1024, 31, "asynchronously")]
        [TestCase(true, true, 128, 31, "threads per group")]
        [TestCase(true, true, 1024, 8, "buffers per compute kernel")]
        public void Auto_FallsBackToTheCpuAndSaysWhy(bool compute, bool readback, int maxWorkGroupSize, int maxBuffers, string because)
        {
            Assert.That(FluidBackendChoice.UseGpu(FluidBackend.Auto, compute, readback, maxWorkGroupSize, maxBuffers, out string reason), Is.False);
            Assert.That(reason, Does.Contain(because));
        }
    }
}
