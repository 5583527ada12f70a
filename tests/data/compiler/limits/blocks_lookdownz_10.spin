PUB main | x
  x := lookdownz(x: lookdownz(x: lookdownz(x: lookdownz(x: lookdownz(x: lookdownz(x: lookdownz(x: lookdownz(x: lookdownz(x: lookdownz(x: 1))))))))))
