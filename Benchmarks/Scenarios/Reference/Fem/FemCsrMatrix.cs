using System;
using System.Collections.Generic;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// A square sparse matrix in compressed sparse row form (row starts, sorted column indices, values), float64.
    /// The pattern is fixed at construction (the couplings of the finite-element mesh); values are accumulated with
    /// <see cref="Add"/>.
    /// </summary>
    public sealed class FemCsrMatrix
    {
        /// <summary>Rows (= columns).</summary>
        public readonly int Size;
        /// <summary>Row r occupies [RowStart[r], RowStart[r + 1]) of <see cref="Columns"/> and <see cref="Values"/>.</summary>
        public readonly int[] RowStart;
        /// <summary>Column indices, ascending within a row.</summary>
        public readonly int[] Columns;
        /// <summary>Entries.</summary>
        public readonly double[] Values;

        /// <summary>A matrix with the pattern of <paramref name="pattern"/> and zero values.</summary>
        public FemCsrMatrix(FemCsrMatrix pattern)
        {
            Size = pattern.Size;
            RowStart = pattern.RowStart;
            Columns = pattern.Columns;
            Values = new double[Columns.Length];
        }

        /// <summary>A matrix whose row r has the (distinct) columns of <paramref name="rows"/>[r], zero values.</summary>
        public FemCsrMatrix(List<int>[] rows)
        {
            Size = rows.Length;
            RowStart = new int[Size + 1];
            for (int r = 0; r < Size; r++)
                RowStart[r + 1] = RowStart[r] + rows[r].Count;
            Columns = new int[RowStart[Size]];
            for (int r = 0; r < Size; r++)
            {
                rows[r].Sort();
                rows[r].CopyTo(Columns, RowStart[r]);
            }
            Values = new double[Columns.Length];
        }

        /// <summary>Sets every entry to zero.</summary>
        public void Clear() => Array.Clear(Values, 0, Values.Length);

        /// <summary>Adds v to entry (row, column), which must be in the pattern.</summary>
        public void Add(int row, int column, double v)
        {
            int k = Array.BinarySearch(Columns, RowStart[row], RowStart[row + 1] - RowStart[row], column);
            if (k < 0)
                throw new InvalidOperationException("Entry outside the sparsity pattern.");
            Values[k] += v;
        }

        /// <summary>The entry (row, column), zero outside the pattern.</summary>
        public double Get(int row, int column)
        {
            int k = Array.BinarySearch(Columns, RowStart[row], RowStart[row + 1] - RowStart[row], column);
            return k < 0 ? 0 : Values[k];
        }

        /// <summary>y = A x.</summary>
        public void Multiply(ReadOnlySpan<double> x, Span<double> y)
        {
            for (int r = 0; r < Size; r++)
            {
                double s = 0;
                for (int k = RowStart[r]; k < RowStart[r + 1]; k++)
                    s += Values[k] * x[Columns[k]];
                y[r] = s;
            }
        }

        /// <summary>max |r − c| over the pattern.</summary>
        public int Bandwidth
        {
            get
            {
                int b = 0;
                for (int r = 0; r < Size; r++)
                for (int k = RowStart[r]; k < RowStart[r + 1]; k++)
                    b = Math.Max(b, Math.Abs(r - Columns[k]));
                return b;
            }
        }

        /// <summary>A + s B (same pattern), written into this.</summary>
        public void SetSum(FemCsrMatrix a, double s, FemCsrMatrix b)
        {
            for (int k = 0; k < Values.Length; k++)
                Values[k] = a.Values[k] + s * b.Values[k];
        }
    }
}
