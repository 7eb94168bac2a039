using NUnit.Framework;
using SoftBodyDynamics.Lavapipe;

namespace SoftBodyDynamics.Tests.Compute
{
    /// <summary>
    /// One lavapipe device, one compiled FluidSolver.compute and one fluid surface renderer (Shaders/FluidSurface.compute) for the whole run. The device runs under the Khronos
    /// validation layer (when installed) so a binding or layout mistake fails the test that made it.
    /// </summary>
    [SetUpFixture]
    public sealed class Lavapipe
    {
        public static LavapipeDevice Device { get; private set; }
        public static LavapipeComputeShader FluidShader { get; private set; }
        public static LavapipeFluidSurface Surface { get; private set; }

        [OneTimeSetUp]
        public void Start()
        {
            System.Environment.SetEnvironmentVariable("VKH_VALIDATION", "1");
            Device = new LavapipeDevice();
            FluidShader = new LavapipeComputeShader(Device, LavapipeFluidSolver.ComputePath());
            Surface = new LavapipeFluidSurface(Device);
            TestContext.Progress.WriteLine($"device: {Device.DeviceName}, validation layer: {(Device.ValidationEnabled ? "on" : "not installed")}");
        }

        [OneTimeTearDown]
        public void Stop()
        {
            Surface?.Dispose();
            FluidShader?.Dispose();
            Device?.Dispose();
        }

        /// <summary>No validation message so far.</summary>
        public static void AssertValid() =>
            Assert.That(Device.ValidationMessages, Is.Zero, "the Vulkan validation layer reported problems (see the test output)");
    }
}
