#!/usr/bin/env python3
"""Writes reference-overloads.txt: every public static method, operator and conversion of com.unity.mathematics
whose declaring type the stand-in also declares, read from the package source (Unity.Mathematics/*.cs).
Usage: python3 reference-overloads.py PATH/TO/com.unity.mathematics/Unity.Mathematics VERSION > reference-overloads.txt"""
import glob, os, re, sys

DECL = re.compile(r'\b(?:struct|class)\s+(\w+)')
METHOD = re.compile(r'public\s+static\s+(?:unsafe\s+)?(?:extern\s+)?[\w\.\[\]<>]+\s+(\w+)\s*\(([^)]*)\)')
OPERATOR = re.compile(r'public\s+static\s+(?:unsafe\s+)?[\w\.\[\]]+\s+operator\s*([^\s(]+)\s*\(([^)]*)\)')
CONVERSION = re.compile(r'public\s+static\s+(implicit|explicit)\s+operator\s+([\w\.]+)\s*\(([^)]*)\)')
OPERATORS = {'+': 'op_Addition', '-': 'op_Subtraction', '*': 'op_Multiply', '/': 'op_Division', '%': 'op_Modulus',
             '==': 'op_Equality', '!=': 'op_Inequality', '<': 'op_LessThan', '>': 'op_GreaterThan',
             '<=': 'op_LessThanOrEqual', '>=': 'op_GreaterThanOrEqual', '&': 'op_BitwiseAnd', '|': 'op_BitwiseOr',
             '^': 'op_ExclusiveOr', '~': 'op_OnesComplement', '!': 'op_LogicalNot', '++': 'op_Increment',
             '--': 'op_Decrement', '<<': 'op_LeftShift', '>>': 'op_RightShift'}


def parameters(text):
    types = []
    for p in text.split(','):
        p = re.sub(r'=.*$', '', p.strip()).strip()
        if not p:
            continue
        p = re.sub(r'^(this|in|ref|out|params)\s+', '', p)
        types.append(re.sub(r'\s+', ' ', p.rsplit(' ', 1)[0]))
    return types


def members(folder):
    found = set()
    for path in sorted(glob.glob(os.path.join(folder, '*.cs'))):
        owner = None
        for line in open(path, encoding='utf-8'):
            s = line.strip()
            if s.startswith('//'):
                continue
            d = DECL.search(s)
            if d and not s.startswith('return'):
                owner = d.group(1)
            if owner is None or 'public static' not in s:
                continue
            c = CONVERSION.search(s)
            if c:
                found.add(f'{owner}.op_{c.group(1).capitalize()}({", ".join(parameters(c.group(3)))}) -> {c.group(2)}')
                continue
            o = OPERATOR.search(s)
            if o:
                ps = parameters(o.group(2))
                name = OPERATORS.get(o.group(1), 'op_' + o.group(1))
                if o.group(1) in ('+', '-') and len(ps) == 1:
                    name = 'op_UnaryPlus' if o.group(1) == '+' else 'op_UnaryNegation'
                found.add(f'{owner}.{name}({", ".join(ps)})')
                continue
            m = METHOD.search(s)
            if m:
                found.add(f'{owner}.{m.group(1)}({", ".join(parameters(m.group(2)))})')
    return found


def main():
    source, version = sys.argv[1], sys.argv[2]
    here = os.path.dirname(os.path.abspath(__file__))
    stand_in = {m.split('.', 1)[0] for m in members(here)}
    print(f'# Public static methods, operators and conversions of com.unity.mathematics {version} whose type the stand-in')
    print('# declares, one per line: Type.Name(parameter types) [-> conversion target]. Written by reference-overloads.py;')
    print('# read by OverloadConformanceTests (Tools~/DotNet/SoftBodyDynamics.Tests.MathematicsStandIn).')
    for m in sorted(x for x in members(source) if x.split('.', 1)[0] in stand_in):
        print(m)


if __name__ == '__main__':
    main()
