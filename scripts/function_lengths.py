#!/usr/bin/env python3
"""Lists the functions longer than LIM lines (default 40; CONTRIBUTING: functions under ~40).

Usage: LIM=40 scripts/function_lengths.py $(git ls-files 'include/*.hpp' 'examples/*.cpp')
       scripts/function_lengths.py --max 44 include examples   # the check CI runs
       scripts/function_lengths.py --self-test

With --max N, the arguments may be folders (their .hpp/.cpp files, recursively), the
functions longer than N lines are listed with file:line, and the exit status is 1 if there is
one (ctest function_lengths, label fast: no function over 44 lines, ~40 with some slack for
the heuristic). --self-test checks on a temporary file that a function of 45 lines fails it and
one of 44 does not (the check can fail).

A function's length is counted from the first line of its signature (template line
included, comments not) to its closing brace. The parse is a heuristic (comments, strings and
preprocessor lines blanked, braces matched at namespace and class scope), not a C++ parser:
lambdas count with their enclosing function, and a statement it misreads is skipped.
"""
import re, sys, pathlib

def strip(src):
    out=[]; i=0; n=len(src)
    while i<n:
        c=src[i]
        if src.startswith('//',i):
            j=src.find('\n',i); j=n if j<0 else j; out.append(' '*(j-i)); i=j
        elif src.startswith('/*',i):
            j=src.find('*/',i+2); j=n if j<0 else j+2
            out.append(''.join(ch if ch=='\n' else ' ' for ch in src[i:j])); i=j
        elif c=='R' and src.startswith('R"',i):
            m=re.match(r'R"([^(]*)\(',src[i:]); d=m.group(1); end=src.find(')'+d+'"',i)
            j=end+len(d)+2; out.append(''.join(ch if ch=='\n' else ' ' for ch in src[i:j])); i=j
        elif c=='"' or (c=="'" and not (i>0 and src[i-1].isalnum())):
            j=i+1
            while j<n and src[j]!=c:
                j+= 2 if src[j]=='\\' else 1
            j+=1; out.append(c+' '*(j-i-2)+c); i=j
        elif c=='#' and (i==0 or src[:i].rstrip(' \t').endswith('\n') or src[:i].rstrip(' \t')==''):
            j=i
            while True:
                k=src.find('\n',j); k=n if k<0 else k
                if src[k-1]=='\\' and k<n: j=k+1; continue
                break
            out.append(''.join(ch if ch=='\n' else ' ' for ch in src[i:k])); i=k
        else:
            out.append(c); i+=1
    return ''.join(out)

def match(s,i):
    d=0
    for j in range(i,len(s)):
        if s[j]=='{': d+=1
        elif s[j]=='}':
            d-=1
            if d==0: return j
    return len(s)-1

CONT=re.compile(r'^\s*(template\s*<.*>\s*)?(namespace|extern\s*"\s*")\b',re.S)
CLASS=re.compile(r'^\s*(template\s*<.*?>\s*)?(class|struct|union)\b',re.S)
ENUM=re.compile(r'^\s*enum\b')
def scan(s, start, end, out, scope):
    i=start; stmt=start
    while i<end:
        c=s[i]
        if c==';': stmt=i+1
        elif c=='}': stmt=i+1
        elif c=='{':
            text=s[stmt:i]; close=match(s,i)
            flat=' '.join(text.split())
            if CONT.match(text) and '(' not in text.split('{')[0] or re.match(r'^\s*(inline\s+)?namespace\b',text):
                scan(s,i+1,close,out,scope); stmt=close+1; i=close+1; continue
            if re.search(r'\b(class|struct|union)\s+\w+[^()]*$',text) and not re.search(r'=',text.split('struct')[-1].split('class')[-1]):
                m=re.search(r'(class|struct|union)\s+(\w+)',text)
                scan(s,i+1,close,out,scope+[m.group(2) if m else '?']); stmt=close+1; i=close+1; continue
            if ENUM.match(text): i=close+1; continue
            pre=s[:i].rstrip()
            if '(' in text and re.search(r'\)\s*:',flat) and re.search(r'[\w>]$',pre) and not re.search(r'\b(const|noexcept|override|final|mutable)$',pre):
                i=close+1; continue   # ctor member init brace
            par=0; eq=False
            for ch_i,ch in enumerate(text):
                if ch in '(<[': par+=1
                elif ch in ')>]': par-=1
                elif ch=='=' and par==0 and 'operator' not in text[max(0,ch_i-10):ch_i]: eq=True
            if '(' in text and not eq:
                m=re.findall(r'(~?[\w:]+|operator\s*[^\s(]+)\s*\(',text)
                name=m[0] if m else '?'
                for cand in m:
                    if cand not in ('requires','noexcept','decltype','alignas','sizeof','template','PDD_ASSERT'): name=cand; break
                first=stmt+len(text)-len(text.lstrip())
                l0=s.count('\n',0,first)+1; l1=s.count('\n',0,close)+1
                out.append((l1-l0+1,'::'.join(scope+[name]),l0))
                i=close+1; stmt=close+1; continue
            i=close+1; continue
        i+=1

def lengths(files):
    res=[]
    for f in files:
        src=pathlib.Path(f).read_text(); s=strip(src); out=[]; scan(s,0,len(s),out,[])
        for n,name,l in out: res.append((n,str(f),l,name))
    res.sort(reverse=True)
    return res

def sources(paths):
    for p in map(pathlib.Path,paths):
        if p.is_dir(): yield from sorted(f for f in p.rglob('*') if f.suffix in ('.hpp','.cpp'))
        else: yield p

def report(res,lim):
    print(f"functions: {len(res)}, over {lim}: {sum(1 for r in res if r[0]>lim)}")
    for n,f,l,name in res:
        if n>lim: print(f"{n:4d}  {f}:{l}  {name}")

def self_test():
    import tempfile
    def fn(name,lines): return f"int {name}(int x) {{\n"+"  x += 1;\n"*(lines-3)+"  return x;\n}\n"
    with tempfile.TemporaryDirectory() as tmp:
        f=pathlib.Path(tmp)/'a.hpp'
        f.write_text("namespace pdd {\nstruct s {\n"+fn('short_one',44)+"};\n"+fn('long_one',45)+"}\n")
        got=[(n,name) for n,_,_,name in lengths(sources([tmp])) if n>44]
    ok=got==[(45,'long_one')]
    print("self-test", "passed" if ok else f"failed: over 44 lines {got}, expected [(45, 'long_one')]")
    return 0 if ok else 1

def main(argv):
    if argv==['--self-test']: return self_test()
    if argv[:1]=='--max'.split():
        lim=int(argv[1]); files=list(sources(argv[2:]))
        if not files: print("no .hpp/.cpp files in", *argv[2:]); return 1
        res=lengths(files); report(res,lim)
        return 1 if any(r[0]>lim for r in res) else 0
    report(lengths(argv),int(__import__('os').environ.get('LIM','40')))
    return 0

if __name__=='__main__':
    sys.exit(main(sys.argv[1:]))
