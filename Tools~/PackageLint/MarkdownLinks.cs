using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using System.Text.RegularExpressions;

namespace SoftBodyDynamics.PackageLint
{
    /// <summary>
    /// Relative links and images in markdown files: the target file must exist, and an anchor must name a heading of
    /// the target (GitHub's slugs). Links with a URI scheme (https:, mailto:, …) are not followed.
    /// </summary>
    static class MarkdownLinks
    {
        /// <summary>Problems of every relative link in <paramref name="files"/> (paths relative to <paramref name="root"/>).</summary>
        public static List<string> Check(string root, IEnumerable<string> files)
        {
            var problems = new List<string>();
            var anchorCache = new Dictionary<string, HashSet<string>>();
            foreach (string rel in files)
            {
                string path = Path.Combine(root, rel);
                string text = File.ReadAllText(path);
                string dir = Path.GetDirectoryName(path);
                foreach ((string target, int line) in Links(text))
                {
                    string where = $"{rel}:{line}: ({target})";
                    if (s_Scheme.IsMatch(target)) continue;
                    int hash = target.IndexOf('#');
                    string filePart = hash < 0 ? target : target.Substring(0, hash);
                    string anchor = hash < 0 ? null : Uri.UnescapeDataString(target.Substring(hash + 1));
                    string resolved = path;
                    if (filePart.Length > 0)
                    {
                        int query = filePart.IndexOf('?');
                        if (query >= 0) filePart = filePart.Substring(0, query);
                        resolved = Path.GetFullPath(Path.Combine(dir, Uri.UnescapeDataString(filePart)));
                        string fromRoot = Path.GetRelativePath(root, resolved);
                        if (fromRoot.StartsWith("..") || Path.IsPathRooted(fromRoot))
                        {
                            problems.Add($"{where} points outside the package");
                            continue;
                        }
                        if (!File.Exists(resolved) && !Directory.Exists(resolved))
                        {
                            problems.Add($"{where}: no file {fromRoot.Replace('\\', '/')}");
                            continue;
                        }
                    }
                    if (string.IsNullOrEmpty(anchor) || !resolved.EndsWith(".md", StringComparison.OrdinalIgnoreCase)
                        || !File.Exists(resolved))
                        continue;
                    if (!anchorCache.TryGetValue(resolved, out HashSet<string> anchors))
                        anchorCache[resolved] = anchors = Anchors(File.ReadAllText(resolved));
                    if (!anchors.Contains(anchor))
                        problems.Add($"{where}: no heading with the anchor #{anchor} in {Path.GetRelativePath(root, resolved).Replace('\\', '/')}");
                }
            }
            return problems;
        }

        /// <summary>A URI scheme (https:, mailto:, …): an external link.</summary>
        static readonly Regex s_Scheme = new Regex(@"^[A-Za-z][A-Za-z0-9+.-]*:");

        /// <summary>Inline links and images: [text](target "title"), text with one level of nested brackets.</summary>
        static readonly Regex s_InlineLink = new Regex(
            @"!?\[(?:[^\[\]]|\[[^\[\]]*\])*\]\(\s*(?:<([^>\n]*)>|([^\s()]*(?:\([^\s()]*\)[^\s()]*)*))(?:\s+(?:""[^""]*""|'[^']*'|\([^)]*\)))?\s*\)");

        /// <summary>Reference definitions: [label]: target.</summary>
        static readonly Regex s_Definition = new Regex(@"^ {0,3}\[[^\]]+\]:\s*<?([^\s>]+)>?", RegexOptions.Multiline);

        /// <summary>Every link target with its 1-based line, outside fenced code and code spans.</summary>
        static IEnumerable<(string target, int line)> Links(string text)
        {
            string prose = BlankCode(text);
            foreach (Match m in s_InlineLink.Matches(prose))
            {
                string target = m.Groups[1].Success ? m.Groups[1].Value : m.Groups[2].Value;
                int line = LineOf(prose, m.Index);
                yield return (target, line);
                // An image inside a link's text ([![alt](image)](target)) is a link too.
                string inner = m.Value.Substring(0, m.Value.LastIndexOf("]("));
                foreach (Match n in s_InlineLink.Matches(inner, 1))
                    yield return (n.Groups[1].Success ? n.Groups[1].Value : n.Groups[2].Value, line);
            }
            foreach (Match m in s_Definition.Matches(prose)) yield return (m.Groups[1].Value, LineOf(prose, m.Index));
            foreach (Match m in s_HtmlSource.Matches(prose)) yield return (m.Groups[1].Value, LineOf(prose, m.Index));
        }

        /// <summary>HTML images and links in Markdown: &lt;img src="…"&gt;, &lt;a href="…"&gt;.</summary>
        static readonly Regex s_HtmlSource = new Regex(@"<(?:img|a)\s[^>]*\b(?:src|href)\s*=\s*[""']([^""']+)[""']", RegexOptions.IgnoreCase);

        static int LineOf(string text, int index)
        {
            int line = 1;
            for (int i = 0; i < index; i++) if (text[i] == '\n') line++;
            return line;
        }

        static readonly Regex s_Fence = new Regex(@"^ {0,3}(```+|~~~+)");
        static readonly Regex s_CodeSpan = new Regex(@"(`+)(?:(?!\1).)+?\1", RegexOptions.Singleline);

        /// <summary>The text with fenced code blocks and code spans replaced by spaces (line breaks kept).</summary>
        static string BlankCode(string text)
        {
            var sb = new StringBuilder(text.Length);
            string fence = null;
            foreach (string line in text.Split('\n'))
            {
                Match f = s_Fence.Match(line);
                bool isCode = fence != null;
                if (f.Success)
                {
                    string marker = f.Groups[1].Value;
                    if (fence == null) { fence = marker; isCode = true; }
                    else if (marker[0] == fence[0] && marker.Length >= fence.Length && line.Trim() == marker) { fence = null; isCode = true; }
                }
                sb.Append(isCode ? new string(' ', line.Length) : line).Append('\n');
            }
            sb.Length--;
            return s_CodeSpan.Replace(sb.ToString(), m => Regex.Replace(m.Value, @"[^\n]", " "));
        }

        static readonly Regex s_Atx = new Regex(@"^ {0,3}#{1,6}(?:[ \t]+(.*?))?(?:[ \t]+#+)?[ \t]*$");
        static readonly Regex s_Setext = new Regex(@"^ {0,3}(=+|-+)[ \t]*$");
        static readonly Regex s_HtmlAnchor = new Regex(@"<a\s[^>]*\b(?:name|id)\s*=\s*[""']([^""']+)[""']", RegexOptions.IgnoreCase);

        /// <summary>The anchors GitHub gives a markdown file: heading slugs (with -1, -2… for repeats) and HTML anchors.</summary>
        public static HashSet<string> Anchors(string text)
        {
            var anchors = new HashSet<string>(StringComparer.Ordinal);
            var seen = new Dictionary<string, int>();
            string[] lines = text.Split('\n').Select(l => l.TrimEnd('\r')).ToArray();
            string fence = null;
            for (int i = 0; i < lines.Length; i++)
            {
                string line = lines[i];
                Match f = s_Fence.Match(line);
                if (f.Success)
                {
                    string marker = f.Groups[1].Value;
                    if (fence == null) fence = marker;
                    else if (marker[0] == fence[0] && marker.Length >= fence.Length && line.Trim() == marker) fence = null;
                    continue;
                }
                if (fence != null) continue;
                foreach (Match a in s_HtmlAnchor.Matches(line)) anchors.Add(a.Groups[1].Value);
                string heading = null;
                Match atx = s_Atx.Match(line);
                if (atx.Success) heading = atx.Groups[1].Value;
                else if (i + 1 < lines.Length && line.Trim().Length > 0 && s_Setext.IsMatch(lines[i + 1])
                         && !line.TrimStart().StartsWith("|") && !s_Setext.IsMatch(line))
                    heading = line.Trim();
                if (heading == null) continue;
                string slug = Slug(heading);
                if (seen.TryGetValue(slug, out int n)) { seen[slug] = n + 1; anchors.Add($"{slug}-{n + 1}"); }
                else { seen[slug] = 0; anchors.Add(slug); }
            }
            return anchors;
        }

        /// <summary>
        /// GitHub's heading anchor: the heading's text without inline markup, lowercased; every space becomes '-';
        /// letters, marks, numbers, '-' and '_' are kept and every other character (punctuation, symbols) dropped.
        /// </summary>
        public static string Slug(string heading)
        {
            string t = Regex.Replace(heading, @"!?\[((?:[^\[\]]|\[[^\[\]]*\])*)\]\([^)]*\)", "$1");   // links, images: their text
            t = Regex.Replace(t, @"<[^>]+>", "");                                                  // HTML tags
            t = t.Replace("`", "").Replace("*", "");
            t = Regex.Replace(t, @"(^|\s)_+|_+(\s|$)", "$1$2");                                     // _emphasis_
            var sb = new StringBuilder(t.Length);
            foreach (char c in t.Trim().ToLowerInvariant())
            {
                UnicodeCategory cat = char.GetUnicodeCategory(c);
                if (c == ' ') sb.Append('-');
                else if (c == '-' || c == '_' || char.IsLetterOrDigit(c)
                         || cat == UnicodeCategory.NonSpacingMark || cat == UnicodeCategory.SpacingCombiningMark
                         || cat == UnicodeCategory.EnclosingMark || cat == UnicodeCategory.LetterNumber
                         || cat == UnicodeCategory.OtherNumber)
                    sb.Append(c);
            }
            return sb.ToString();
        }
    }
}
