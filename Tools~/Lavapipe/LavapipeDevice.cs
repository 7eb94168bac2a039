using System;
using System.Runtime.InteropServices;
using System.Text;

namespace SoftBodyDynamics.Lavapipe
{
    /// <summary>
    /// A Vulkan device through libvkhost: lavapipe (Mesa's CPU driver) unless VK_ICD_FILENAMES is already set to another
    /// driver. Set VKH_VALIDATION=1 to run under the Khronos validation layer (its messages are counted).
    /// </summary>
    public sealed unsafe class LavapipeDevice : IDisposable
    {
        /// <summary>Lavapipe's driver manifest on Debian (x86-64).</summary>
        public const string LavapipeIcd = "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json";

        internal IntPtr Context;
        public string DeviceName { get; }

        public LavapipeDevice()
        {
            VkHost.Touch();
            if (string.IsNullOrEmpty(Environment.GetEnvironmentVariable("VK_ICD_FILENAMES")))
                VkHost.vkh_setenv("VK_ICD_FILENAMES", LavapipeIcd);
            string validation = Environment.GetEnvironmentVariable("VKH_VALIDATION");
            if (!string.IsNullOrEmpty(validation))
                VkHost.vkh_setenv("VKH_VALIDATION", validation);
            byte* error = stackalloc byte[512];
            error[0] = 0;
            int rc = VkHost.vkh_create(out Context, error, 512);
            if (rc != 0)
                throw new InvalidOperationException($"Vulkan device: {Marshal.PtrToStringUTF8((IntPtr)error)} (is mesa-vulkan-drivers installed?)");
            DeviceName = Marshal.PtrToStringUTF8(VkHost.vkh_device_name(Context));
        }

        /// <summary>Buffers alive on the device (a leak check).</summary>
        public int LiveBuffers => VkHost.vkh_live_buffers(Context);
        /// <summary>Pipelines alive on the device.</summary>
        public int LiveKernels => VkHost.vkh_live_kernels(Context);
        /// <summary>Warnings and errors the validation layer reported (0 when it is off).</summary>
        public int ValidationMessages => VkHost.vkh_validation_messages(Context);
        public bool ValidationEnabled => VkHost.vkh_validation_enabled(Context) != 0;

        public LavapipeBuffer CreateBuffer(long bytes) => new LavapipeBuffer(this, bytes);

        /// <summary>Runs the recorded dispatches and waits; returns the milliseconds from submit to completion.</summary>
        public double Submit()
        {
            int rc = VkHost.vkh_submit(Context, out double ms);
            if (rc != 0)
                throw new InvalidOperationException($"vkQueueSubmit/vkWaitForFences failed ({rc})");
            return ms;
        }

        public void Dispose()
        {
            if (Context != IntPtr.Zero)
                VkHost.vkh_destroy(Context);
            Context = IntPtr.Zero;
        }
    }

    /// <summary>A host-visible storage buffer, mapped for its whole life.</summary>
    public sealed unsafe class LavapipeBuffer : IDisposable
    {
        readonly LavapipeDevice m_Device;
        internal IntPtr Handle;
        readonly void* m_Mapped;
        public long Bytes { get; }

        internal LavapipeBuffer(LavapipeDevice device, long bytes)
        {
            m_Device = device;
            Bytes = Math.Max(bytes, 16);
            int rc = VkHost.vkh_buffer_create(device.Context, (ulong)Bytes, out Handle, out m_Mapped);
            if (rc != 0)
                throw new InvalidOperationException($"vkh_buffer_create({Bytes}) failed ({rc})");
        }

        /// <summary>The buffer's memory as elements of <typeparamref name="T"/>.</summary>
        public Span<T> As<T>() where T : unmanaged => new Span<T>(m_Mapped, (int)(Bytes / sizeof(T)));

        public void Dispose()
        {
            if (Handle != IntPtr.Zero)
                VkHost.vkh_buffer_destroy(m_Device.Context, Handle);
            Handle = IntPtr.Zero;
        }
    }
}
