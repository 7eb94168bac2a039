using System;
using System.Collections.Generic;
using System.IO;
using System.Text.RegularExpressions;

namespace SoftBodyDynamics.Tests.Compute
{
    /// <summary>
    /// A <c>cbuffer</c> declaration read from HLSL source, its members placed by the HLSL constant-buffer packing rules:
    /// members follow one another, 4 bytes per component, and a member that would straddle a 16-byte boundary starts the
    /// next 16-byte row; the buffer's size is rounded up to 16 bytes. Scalars and vectors only (a matrix, array or struct
    /// member is rejected, so a declaration this reader cannot place fails loudly).
    /// </summary>
    public sealed class HlslConstantBuffer
    {
        public string Name;
        /// <summary>The members in declaration order: name, HLSL type, byte offset.</summary>
        public List<(string Name, string Type, int Offset)> Members = new List<(string, string, int)>();
        /// <summary>Bytes, rounded up to a multiple of 16.</summary>
        public int Size;

        static readonly Regex Member = new Regex(@"^(?<type>(float|int|uint)(?<n>[1-4])?)\s+(?<name>\w+)\s*;$");

        /// <summary>The cbuffer <paramref name="name"/> of the HLSL file <paramref name="path"/>.</summary>
        public static HlslConstantBuffer Read(string path, string name)
        {
            string source = Regex.Replace(File.ReadAllText(path), @"//[^\n]*|/\*.*?\*/", "", RegexOptions.Singleline);
            Match block = Regex.Match(source, @"\bcbuffer\s+" + Regex.Escape(name) + @"\s*(:\s*register\s*\(\s*\w+\s*\))?\s*\{(?<body>[^}]*)\}");
            if (!block.Success)
                throw new FormatException($"{path}: no cbuffer {name}");
            var result = new HlslConstantBuffer { Name = name };
            int offset = 0;
            foreach (string raw in block.Groups["body"].Value.Split(';'))
            {
                string line = Regex.Replace(raw, @"\s+", " ").Trim();
                if (line.Length == 0)
                    continue;
                Match m = Member.Match(line + ";");
                if (!m.Success)
                    throw new FormatException($"{path}: cbuffer {name}: cannot place member '{line}' (scalars and vectors of float, int, uint only)");
                string type = m.Groups["type"].Value;
                int bytes = 4 * (m.Groups["n"].Success ? int.Parse(m.Groups["n"].Value) : 1);
                if (offset % 16 + bytes > 16)
                    offset = (offset + 15) & ~15;
                result.Members.Add((m.Groups["name"].Value, type, offset));
                offset += bytes;
            }
            result.Size = (offset + 15) & ~15;
            return result;
        }
    }
}
