using NUnit.Framework;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Tests.Solvers
{
    public class FluidBackendChoiceTests
    {
        [Test]
        public void Cpu_IsNeverTheGpu()
        {
            Assert.That(FluidBackendChoice.UseGpu(FluidBackend.Cpu, true, true, false, out string reason), Is.False);
            Assert.That(reason, Is.Null);
        }

        [TestCase(FluidBackend.Auto)]
        [TestCase(FluidBackend.Gpu)]
        public void GpuOrAuto_TakesTheGpuWhenEverythingIsThere(FluidBackend requested)
        {
            Assert.That(FluidBackendChoice.UseGpu(requested, true, true, false, out string reason), Is.True);
            Assert.That(reason, Is.Null);
        }

        [TestCase(false, true, false, "compute shaders")]
        [TestCase(true, false, false, "asynchronously")]
        [TestCase(true, true, true, "colliders")]
        public void Auto_FallsBackToTheCpuAndSaysWhy(bool compute, bool readback, bool colliders, string because)
        {
            Assert.That(FluidBackendChoice.UseGpu(FluidBackend.Auto, compute, readback, colliders, out string reason), Is.False);
            Assert.That(reason, Does.Contain(because));
        }
    }
}
