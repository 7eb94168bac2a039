using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Security.Cryptography;
using System.Text;
using System.Text.Json;
using System.Text.RegularExpressions;

namespace SoftBodyDynamics.Lavapipe
{
    /// <summary>A resource of a kernel, from its SPIR-V's reflection.</summary>
    public sealed class KernelBinding
    {
        public string Name;
        public int Binding;
        public bool Uniform;
    }

    /// <summary>A named constant buffer (HLSL <c>cbuffer</c>) of a kernel, from its SPIR-V's reflection.</summary>
    public sealed class ConstantBlock
    {
        public string Name;
        /// <summary>Bytes up to the end of the last member.</summary>
        public int Size;
        /// <summary>The members in declaration order: name, reflected type (spirv-cross: float, vec3, uint, ivec3…), byte offset.</summary>
        public List<(string Name, string Type, int Offset)> Members = new List<(string, string, int)>();
    }

    /// <summary>One kernel of a .compute file compiled to SPIR-V, with what reflection says of it.</summary>
    public sealed class CompiledKernel
    {
        public string Name;
        public byte[] Spirv;
        public int GroupSizeX, GroupSizeY, GroupSizeZ;
        public List<KernelBinding> Bindings = new List<KernelBinding>();
        /// <summary>Members of the loose-globals block ($Global): name → byte offset.</summary>
        public Dictionary<string, int> GlobalOffsets = new Dictionary<string, int>();
        public int GlobalBlockSize;
        /// <summary>The named constant buffers the kernel reads, by name (bound like Unity's ComputeShader.SetConstantBuffer).</summary>
        public Dictionary<string, ConstantBlock> ConstantBlocks = new Dictionary<string, ConstantBlock>();
    }

    /// <summary>
    /// Compiles every <c>#pragma kernel</c> of a Unity .compute file with glslang's HLSL front end (the flags of
    /// Tools~/ShaderCheck), validates it with spirv-val and reflects it with spirv-cross. Results are cached on disk by a
    /// hash of the shader sources, so a second run costs nothing.
    /// </summary>
    public static class KernelCompiler
    {
        static readonly Regex PragmaKernel = new Regex(@"^\s*#\s*pragma\s+kernel\s+(\w+)(.*)$", RegexOptions.Multiline);

        /// <summary>The kernel names and per-kernel defines of a .compute file, in order.</summary>
        public static List<(string Name, string[] Defines)> Kernels(string computePath)
        {
            var list = new List<(string, string[])>();
            foreach (Match m in PragmaKernel.Matches(File.ReadAllText(computePath)))
                list.Add((m.Groups[1].Value, m.Groups[2].Value.Split(new[] { ' ', '\t', '\r' }, StringSplitOptions.RemoveEmptyEntries)));
            return list;
        }

        /// <summary>Compiles every kernel; <paramref name="defines"/> (NAME or NAME=value) are added to each kernel's own.</summary>
        public static List<CompiledKernel> Compile(string computePath, params string[] defines)
        {
            string dir = Path.GetDirectoryName(Path.GetFullPath(computePath));
            string hash = SourceHash(dir, computePath, defines);
            string cache = Path.Combine(Path.GetTempPath(), "sbd-spirv-cache", hash);
            Directory.CreateDirectory(cache);
            var kernels = Kernels(computePath);
            var result = new CompiledKernel[kernels.Count];
            System.Threading.Tasks.Parallel.For(0, kernels.Count, new System.Threading.Tasks.ParallelOptions { MaxDegreeOfParallelism = 2 }, i =>
            {
                var (name, own) = kernels[i];
                string spv = Path.Combine(cache, name + ".spv"), json = Path.Combine(cache, name + ".json");
                if (!File.Exists(spv) || !File.Exists(json))
                {
                    string tmp = spv + "." + Guid.NewGuid().ToString("N");
                    var args = new List<string> { "-D", "-V", "-S", "comp", "-e", name, "--amb", "--target-env", "vulkan1.1", "--quiet",
                        "-DCI_GLSLANG=1", "-I" + dir, "-o", tmp };
                    args.AddRange(own.Concat(defines).Select(d => "-D" + d));
                    args.Add(computePath);
                    string output = Run("glslangValidator", args, out int rc);
                    if (rc != 0 || output.Contains("ERROR") || output.Contains("Entry point not found"))
                        throw new InvalidOperationException($"glslangValidator failed for {name} (exit {rc}):\n{output}");
                    string val = Run("spirv-val", new List<string> { "--target-env", "vulkan1.1", tmp }, out rc);
                    if (rc != 0)
                        throw new InvalidOperationException($"spirv-val failed for {name}:\n{val}");
                    string reflect = Run("spirv-cross", new List<string> { tmp, "--reflect" }, out rc);
                    if (rc != 0)
                        throw new InvalidOperationException($"spirv-cross --reflect failed for {name}:\n{reflect}");
                    File.WriteAllText(json + ".tmp", reflect);
                    File.Move(json + ".tmp", json, true);
                    File.Move(tmp, spv, true);
                }
                result[i] = Reflect(name, File.ReadAllBytes(spv), File.ReadAllText(json));
            });
            return result.ToList();
        }

        static CompiledKernel Reflect(string name, byte[] spirv, string json)
        {
            var k = new CompiledKernel { Name = name, Spirv = spirv };
            using JsonDocument doc = JsonDocument.Parse(json);
            JsonElement root = doc.RootElement;
            JsonElement size = root.GetProperty("entryPoints")[0].GetProperty("workgroup_size");
            k.GroupSizeX = size[0].GetInt32(); k.GroupSizeY = size[1].GetInt32(); k.GroupSizeZ = size[2].GetInt32();
            if (root.TryGetProperty("ssbos", out JsonElement ssbos))
                foreach (JsonElement b in ssbos.EnumerateArray())
                    k.Bindings.Add(new KernelBinding { Name = b.GetProperty("name").GetString(), Binding = Binding(b), Uniform = false });
            if (root.TryGetProperty("ubos", out JsonElement ubos))
                foreach (JsonElement b in ubos.EnumerateArray())
                {
                    string ubo = b.GetProperty("name").GetString();
                    k.Bindings.Add(new KernelBinding { Name = ubo, Binding = Binding(b), Uniform = true });
                    JsonElement type = root.GetProperty("types").GetProperty(b.GetProperty("type").GetString());
                    if (ubo == "$Global")
                    {
                        k.GlobalBlockSize = b.GetProperty("block_size").GetInt32();
                        foreach (JsonElement m in type.GetProperty("members").EnumerateArray())
                            k.GlobalOffsets[m.GetProperty("name").GetString()] = m.GetProperty("offset").GetInt32();
                        continue;
                    }
                    var block = new ConstantBlock { Name = ubo, Size = b.GetProperty("block_size").GetInt32() };
                    foreach (JsonElement m in type.GetProperty("members").EnumerateArray())
                        block.Members.Add((m.GetProperty("name").GetString(), m.GetProperty("type").GetString(), m.GetProperty("offset").GetInt32()));
                    k.ConstantBlocks[ubo] = block;
                }
            return k;
        }

        static int Binding(JsonElement b)
        {
            if (b.GetProperty("set").GetInt32() != 0)
                throw new InvalidOperationException("every resource must be in descriptor set 0");
            return b.GetProperty("binding").GetInt32();
        }

        static string SourceHash(string dir, string computePath, string[] defines)
        {
            using var sha = SHA256.Create();
            var sb = new StringBuilder();
            foreach (string f in Directory.GetFiles(dir, "*.hlsl", SearchOption.AllDirectories).Append(computePath).OrderBy(f => f, StringComparer.Ordinal))
                sb.Append(Path.GetFileName(f)).Append('\n').Append(File.ReadAllText(f)).Append('\n');
            sb.Append(string.Join(" ", defines)).Append('\n');
            sb.Append(Run("glslangValidator", new List<string> { "--version" }, out _));
            return Convert.ToHexString(sha.ComputeHash(Encoding.UTF8.GetBytes(sb.ToString()))).Substring(0, 24);
        }

        static string Run(string tool, List<string> args, out int exitCode)
        {
            var psi = new ProcessStartInfo(tool) { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
            foreach (string a in args) psi.ArgumentList.Add(a);
            using Process p = Process.Start(psi);
            var stderr = p.StandardError.ReadToEndAsync();
            string stdout = p.StandardOutput.ReadToEnd();
            p.WaitForExit();
            exitCode = p.ExitCode;
            return stdout + stderr.Result;
        }
    }
}
