PUB main | x
  x := lookup(x: lookup(x: lookup(x: lookup(x: lookup(x: lookup(x: lookup(x: lookup(x: lookup(x: lookup(x: 1))))))))))
