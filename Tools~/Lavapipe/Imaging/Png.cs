using System;
using System.IO;
using System.IO.Compression;
using System.Text;

namespace SoftBodyDynamics.Lavapipe.Imaging
{
    /// <summary>
    /// PNG files of 8-bit RGBA pixels (ISO/IEC 15948): written with filter 0 and zlib, read back for RGB or RGBA at 8 bits,
    /// non-interlaced, with any of the five filters. Enough for the renderer's images and their references.
    /// </summary>
    public static class Png
    {
        static readonly byte[] Signature = { 137, 80, 78, 71, 13, 10, 26, 10 };

        /// <summary>Encodes <paramref name="rgba"/> (top row first, 4 bytes per pixel).</summary>
        public static byte[] Encode(int width, int height, byte[] rgba)
        {
            if (rgba.Length != width * height * 4)
                throw new ArgumentException("rgba must hold width × height × 4 bytes");
            using var file = new MemoryStream();
            file.Write(Signature);
            var header = new byte[13];
            WriteBigEndian(header, 0, (uint)width);
            WriteBigEndian(header, 4, (uint)height);
            header[8] = 8;   // bit depth
            header[9] = 6;   // RGBA
            WriteChunk(file, "IHDR", header);
            using (var raw = new MemoryStream())
            {
                using (var z = new ZLibStream(raw, CompressionLevel.Optimal, leaveOpen: true))
                    for (int y = 0; y < height; y++)
                    {
                        z.WriteByte(0);
                        z.Write(rgba, y * width * 4, width * 4);
                    }
                WriteChunk(file, "IDAT", raw.ToArray());
            }
            WriteChunk(file, "IEND", Array.Empty<byte>());
            return file.ToArray();
        }

        /// <summary>Decodes an 8-bit RGB or RGBA PNG into RGBA bytes, top row first.</summary>
        public static (int Width, int Height, byte[] Rgba) Decode(byte[] png)
        {
            for (int i = 0; i < Signature.Length; i++)
                if (png[i] != Signature[i])
                    throw new InvalidDataException("not a PNG");
            int pos = 8, width = 0, height = 0, channels = 0;
            using var idat = new MemoryStream();
            while (pos < png.Length)
            {
                int length = (int)ReadBigEndian(png, pos);
                string type = Encoding.ASCII.GetString(png, pos + 4, 4);
                int data = pos + 8;
                if (type == "IHDR")
                {
                    width = (int)ReadBigEndian(png, data);
                    height = (int)ReadBigEndian(png, data + 4);
                    if (png[data + 8] != 8 || (png[data + 9] != 2 && png[data + 9] != 6) || png[data + 12] != 0)
                        throw new InvalidDataException("only 8-bit RGB or RGBA, non-interlaced PNGs are read");
                    channels = png[data + 9] == 6 ? 4 : 3;
                }
                else if (type == "IDAT")
                    idat.Write(png, data, length);
                else if (type == "IEND")
                    break;
                pos = data + length + 4;
            }
            int stride = width * channels;
            var rows = new byte[height * stride];
            idat.Position = 0;
            using (var z = new ZLibStream(idat, CompressionMode.Decompress))
            {
                var previous = new byte[stride];
                var line = new byte[stride];
                for (int y = 0; y < height; y++)
                {
                    int filter = z.ReadByte();
                    ReadExactly(z, line);
                    for (int i = 0; i < stride; i++)
                    {
                        int a = i >= channels ? line[i - channels] : 0, b = previous[i], c = i >= channels ? previous[i - channels] : 0;
                        int add = filter switch
                        {
                            0 => 0,
                            1 => a,
                            2 => b,
                            3 => (a + b) / 2,
                            4 => Paeth(a, b, c),
                            _ => throw new InvalidDataException($"unknown PNG filter {filter}"),
                        };
                        line[i] = (byte)(line[i] + add);
                    }
                    Buffer.BlockCopy(line, 0, rows, y * stride, stride);
                    (previous, line) = (line, previous);
                }
            }
            if (channels == 4)
                return (width, height, rows);
            var rgba = new byte[width * height * 4];
            for (int i = 0; i < width * height; i++)
            {
                rgba[4 * i] = rows[3 * i];
                rgba[4 * i + 1] = rows[3 * i + 1];
                rgba[4 * i + 2] = rows[3 * i + 2];
                rgba[4 * i + 3] = 255;
            }
            return (width, height, rgba);
        }

        static int Paeth(int a, int b, int c)
        {
            int p = a + b - c, pa = Math.Abs(p - a), pb = Math.Abs(p - b), pc = Math.Abs(p - c);
            return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
        }

        static void ReadExactly(Stream s, byte[] buffer)
        {
            int read = 0;
            while (read < buffer.Length)
            {
                int n = s.Read(buffer, read, buffer.Length - read);
                if (n <= 0)
                    throw new InvalidDataException("PNG data ends early");
                read += n;
            }
        }

        static void WriteChunk(Stream s, string type, byte[] data)
        {
            var head = new byte[8];
            WriteBigEndian(head, 0, (uint)data.Length);
            Encoding.ASCII.GetBytes(type, 0, 4, head, 4);
            s.Write(head);
            s.Write(data);
            uint crc = Crc32(head, 4, 4, 0xFFFFFFFFu);
            crc = Crc32(data, 0, data.Length, crc) ^ 0xFFFFFFFFu;
            var tail = new byte[4];
            WriteBigEndian(tail, 0, crc);
            s.Write(tail);
        }

        static uint[] s_CrcTable;

        /// <summary>CRC-32 (ISO 3309, polynomial 0xEDB88320) as the PNG specification's annex D computes it.</summary>
        static uint Crc32(byte[] data, int offset, int count, uint crc)
        {
            if (s_CrcTable == null)
            {
                var table = new uint[256];
                for (uint n = 0; n < 256; n++)
                {
                    uint c = n;
                    for (int k = 0; k < 8; k++)
                        c = (c & 1) != 0 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
                    table[n] = c;
                }
                s_CrcTable = table;
            }
            for (int i = offset; i < offset + count; i++)
                crc = s_CrcTable[(crc ^ data[i]) & 0xFF] ^ (crc >> 8);
            return crc;
        }

        static void WriteBigEndian(byte[] b, int at, uint v)
        {
            b[at] = (byte)(v >> 24);
            b[at + 1] = (byte)(v >> 16);
            b[at + 2] = (byte)(v >> 8);
            b[at + 3] = (byte)v;
        }

        static uint ReadBigEndian(byte[] b, int at) => (uint)(b[at] << 24 | b[at + 1] << 16 | b[at + 2] << 8 | b[at + 3]);
    }
}
