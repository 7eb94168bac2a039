using System;
using System.IO;
using System.Reflection;
using System.Runtime.InteropServices;

namespace SoftBodyDynamics.Lavapipe
{
    /// <summary>P/Invoke declarations of libvkhost.so (Tools~/VulkanHost/vkhost.c), loaded from the assembly's folder.</summary>
    static unsafe class VkHost
    {
        const string Library = "vkhost";

        static VkHost()
        {
            NativeLibrary.SetDllImportResolver(typeof(VkHost).Assembly, Resolve);
        }

        static IntPtr Resolve(string name, Assembly assembly, DllImportSearchPath? path)
        {
            if (name != Library)
                return IntPtr.Zero;
            string local = Path.Combine(AppContext.BaseDirectory, "libvkhost.so");
            return File.Exists(local) ? NativeLibrary.Load(local) : IntPtr.Zero;
        }

        /// <summary>Runs the static constructor (installs the resolver) before the first call.</summary>
        public static void Touch() { }

        [DllImport(Library)] public static extern int vkh_setenv(string name, string value);
        [DllImport(Library)] public static extern int vkh_create(out IntPtr ctx, byte* error, int errorLength);
        [DllImport(Library)] public static extern void vkh_destroy(IntPtr ctx);
        [DllImport(Library)] public static extern IntPtr vkh_device_name(IntPtr ctx);
        [DllImport(Library)] public static extern int vkh_live_buffers(IntPtr ctx);
        [DllImport(Library)] public static extern int vkh_live_kernels(IntPtr ctx);
        [DllImport(Library)] public static extern int vkh_validation_messages(IntPtr ctx);
        [DllImport(Library)] public static extern int vkh_validation_enabled(IntPtr ctx);
        [DllImport(Library)] public static extern int vkh_buffer_create(IntPtr ctx, ulong size, out IntPtr buffer, out void* mapped);
        [DllImport(Library)] public static extern void vkh_buffer_destroy(IntPtr ctx, IntPtr buffer);
        [DllImport(Library)] public static extern int vkh_kernel_create(IntPtr ctx, byte* spirv, ulong bytes, string entry, int count,
            int* bindings, int* kinds, out IntPtr kernel, byte* error, int errorLength);
        [DllImport(Library)] public static extern void vkh_kernel_destroy(IntPtr ctx, IntPtr kernel);
        [DllImport(Library)] public static extern int vkh_dispatch(IntPtr ctx, IntPtr kernel, int count, IntPtr* buffers, ulong* offsets,
            ulong* ranges, uint gx, uint gy, uint gz, IntPtr indirect, ulong indirectOffset);
        [DllImport(Library)] public static extern int vkh_submit(IntPtr ctx, out double milliseconds);
    }
}
