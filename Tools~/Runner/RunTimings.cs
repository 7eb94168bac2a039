using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace SoftBodyDynamics.Runner
{
    /// <summary>
    /// Wall-clock seconds of each step of a run (a scenario: setup, warm-up, timed steps and evaluation; or a report part),
    /// kept in timings.csv of the report folder so that the next run can say how long it has left.
    /// </summary>
    sealed class RunTimings
    {
        public const string FileName = "timings.csv";
        const string k_Header = "key,seconds";

        /// <summary>The previous run's timings (saved again with this run's) and the reference run's (only read).</summary>
        readonly Dictionary<string, double> m_Previous, m_Reference;
        readonly Dictionary<string, double> m_Current = new Dictionary<string, double>();

        RunTimings(Dictionary<string, double> previous, Dictionary<string, double> reference)
        {
            m_Previous = previous;
            m_Reference = reference;
        }

        public static RunTimings Empty() => new RunTimings(new Dictionary<string, double>(), new Dictionary<string, double>());

        /// <summary>
        /// The timings of the previous run in <paramref name="dir"/>, over those of <paramref name="reference"/> (a file of the
        /// same form: timings of a reference run, so that a first run has an estimate too); empty where neither has a step.
        /// </summary>
        public static RunTimings Load(string dir, string reference = null)
        {
            var previous = new Dictionary<string, double>();
            var referenceRun = new Dictionary<string, double>();
            if (reference != null)
                Read(reference, referenceRun);
            Read(Path.Combine(dir, FileName), previous);
            return new RunTimings(previous, referenceRun);
        }

        static void Read(string path, Dictionary<string, double> previous)
        {
            if (File.Exists(path))
            {
                foreach (string line in File.ReadLines(path))
                {
                    if (line == k_Header)
                        continue;
                    int comma = line.LastIndexOf(',');
                    if (comma <= 0)
                        continue;
                    if (double.TryParse(line.Substring(comma + 1), NumberStyles.Float, CultureInfo.InvariantCulture, out double s) && s >= 0)
                        previous[Unquote(line.Substring(0, comma))] = s;
                }
            }
        }

        /// <summary>The key of one step of a run: suite and scenario text, stable from run to run.</summary>
        public static string Key(string suite, string step) => suite + " | " + step;

        /// <summary>Seconds the previous run took for <paramref name="key"/>, or null.</summary>
        public double? Previous(string key) =>
            m_Previous.TryGetValue(key, out double s) || m_Reference.TryGetValue(key, out s) ? s : (double?)null;

        public void Record(string key, double seconds) => m_Current[key] = seconds;

        /// <summary>
        /// Writes this run's timings, keeping the previous run's for steps this run did not take (a filtered run does not
        /// forget the others).
        /// </summary>
        public void Save(string dir)
        {
            var merged = new SortedDictionary<string, double>(m_Previous, StringComparer.Ordinal);
            foreach (var kv in m_Current)
                merged[kv.Key] = kv.Value;
            var sb = new StringBuilder(k_Header).Append('\n');
            foreach (var kv in merged)
                sb.Append(Quote(kv.Key)).Append(',').Append(kv.Value.ToString("0.###", CultureInfo.InvariantCulture)).Append('\n');
            ReportFiles.WriteAtomically(Path.Combine(dir, FileName), sb.ToString());
        }

        static string Quote(string s) => "\"" + s.Replace("\"", "\"\"") + "\"";

        static string Unquote(string s) =>
            s.Length >= 2 && s[0] == '"' && s[s.Length - 1] == '"' ? s.Substring(1, s.Length - 2).Replace("\"\"", "\"") : s;
    }

    /// <summary>
    /// The estimate of what a run has left: each step not yet taken costs what it took last time, scaled by how much faster
    /// or slower this run's finished steps were than last time; a step never timed costs the mean of this run's finished steps.
    /// </summary>
    sealed class ProgressEstimate
    {
        readonly RunTimings m_Timings;
        readonly IReadOnlyList<string> m_Keys;
        readonly int m_ExcludedFromMean;
        double m_FinishedSeconds, m_FinishedPrevious, m_FinishedWithPrevious;
        int m_Finished;

        /// <param name="excludedFromMean">A step that is not like the others (the preparation step), left out of the mean; −1 for none.</param>
        public ProgressEstimate(RunTimings timings, IReadOnlyList<string> keys, int excludedFromMean = -1)
        {
            m_Timings = timings;
            m_Keys = keys;
            m_ExcludedFromMean = excludedFromMean;
        }

        /// <summary>Step <paramref name="index"/> finished in <paramref name="seconds"/>.</summary>
        public void Finished(int index, double seconds)
        {
            if (index != m_ExcludedFromMean)
            {
                m_Finished++;
                m_FinishedSeconds += seconds;
            }
            double? previous = m_Timings.Previous(m_Keys[index]);
            if (previous.HasValue)
            {
                m_FinishedPrevious += previous.Value;
                m_FinishedWithPrevious += seconds;
            }
        }

        /// <summary>Seconds left before step <paramref name="index"/> starts (it and every later step); null when nothing is known yet.</summary>
        public double? SecondsLeft(int index) => SecondsLeft(index, out int unknown) is double s && unknown == 0 ? s : (double?)null;

        /// <summary>
        /// Seconds the steps from <paramref name="index"/> on take where known (null when none is), and how many of them are
        /// <paramref name="unknown"/>: never timed, with no mean step of this run to count them at yet.
        /// </summary>
        public double? SecondsLeft(int index, out int unknown)
        {
            unknown = 0;
            bool any = false;
            double speed = m_FinishedPrevious > 0 ? m_FinishedWithPrevious / m_FinishedPrevious : 1.0;
            double? mean = m_Finished > 0 ? m_FinishedSeconds / m_Finished : (double?)null;
            double left = 0;
            for (int k = index; k < m_Keys.Count; k++)
            {
                double? previous = m_Timings.Previous(m_Keys[k]);
                if (previous.HasValue)
                    left += previous.Value * speed;
                else if (mean.HasValue && k != m_ExcludedFromMean)
                    left += mean.Value;
                else
                {
                    unknown++;
                    continue;
                }
                any = true;
            }
            return any ? left : (double?)null;
        }

        /// <summary>m:ss (or h:mm:ss).</summary>
        public static string Clock(double seconds)
        {
            var t = TimeSpan.FromSeconds(Math.Max(0, Math.Round(seconds)));
            return t.TotalHours >= 1 ? $"{(int)t.TotalHours}:{t.Minutes:00}:{t.Seconds:00}" : $"{t.Minutes}:{t.Seconds:00}";
        }
    }
}
